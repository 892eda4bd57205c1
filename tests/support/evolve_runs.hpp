#pragma once
// Test support: robozoo-evolve runs of known sizes, as command lines.
#include <string>
#include <vector>

#include "evolve/io/event_log.hpp"
#include "tests/support/subprocess.hpp"

namespace robozoo::testing {

// The runs below are feed-forward (the default regime) with a bias input of 1.0, M1 and
// M2's: at the default 0.3 no feed-forward CPPN grows beyond the root before mutation
// (docs/method.md section 2.1), and these runs must send robots to the simulator.
// A small run that still sends robots to the simulator: 4 generations of 24.
inline const std::vector<std::string> kSmall = {"--seed",  "7",   "--population", "24",    "--generations",        "4",
                                                "--steps", "400", "--quiet",      "--set", "growth.bias_input=1.0"};

// A run long enough (about 1.5 s on 2 cores) to be interrupted at several moments.
inline const std::vector<std::string> kLonger = {
    "--seed",  "7",    "--population", "40",    "--generations",        "8",
    "--steps", "1000", "--quiet",      "--set", "growth.bias_input=1.0"};

inline std::vector<std::string> evolve_args(const std::string& log, int workers, std::vector<std::string> extra = {},
                                            const std::vector<std::string>& size = kSmall) {
  std::vector<std::string> a = {bin("robozoo-evolve"), "--log", log, "--workers", std::to_string(workers)};
  a.insert(a.end(), size.begin(), size.end());
  a.insert(a.end(), extra.begin(), extra.end());
  return a;
}

/// A shell command line of single-quoted words.
inline std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += "'" + x + "' ";
  return s;
}

/// Events of a channel in a log.
inline size_t count_channel(const LogContents& log, const std::string& channel) {
  size_t n = 0;
  for (const auto& r : log.records) n += r.channel == channel;
  return n;
}

}  // namespace robozoo::testing
