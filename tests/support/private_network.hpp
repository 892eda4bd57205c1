#pragma once
// Test support: a test that runs again, alone, in a private network namespace
// (`unshare -n`, loopback up), so that its servers and LCM traffic cannot meet
// another test's or the machine's. The outer run starts the same test binary
// with ROBOZOO_PRIVATE_NETWORK set, filtered to the one test, and passes on
// what it printed (without GoogleTest's own lines).
//
//   TEST(Suite, Name) {
//     RUN_IN_PRIVATE_NETWORK(240, true);   // seconds, and a multicast route for LCM
//     ...                                  // runs only inside the namespace
//   }
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>

#include "tests/support/subprocess.hpp"

namespace robozoo::testing {

inline bool inside_private_network() { return std::getenv("ROBOZOO_PRIVATE_NETWORK") != nullptr; }

/// Runs `test` (Suite.Name) of this binary in a private network namespace, at most
/// `timeout_s` seconds; `multicast_route` routes 224.0.0.0/4 through loopback (LCM).
inline void rerun_in_private_network(const std::string& test, int timeout_s, bool multicast_route) {
  char self[4096] = {0};
  ASSERT_GT(::readlink("/proc/self/exe", self, sizeof self - 1), 0);
  const std::string route = multicast_route ? "ip route add 224.0.0.0/4 dev lo && " : "";
  const Outcome o =
      run_shell("timeout " + std::to_string(timeout_s) + " unshare -n sh -c 'ip link set lo up && " + route +
                "ROBOZOO_PRIVATE_NETWORK=1 exec " + std::string(self) + " --gtest_filter=" + test + "'");
  EXPECT_EQ(o.status, 0) << o.output;
  EXPECT_NE(o.output.find("[  PASSED  ] 1 test"), std::string::npos) << o.output;
  std::istringstream lines(o.output);
  for (std::string line; std::getline(lines, line);)
    if (!line.empty() && line[0] != '[' && line.rfind("Running main", 0) != 0 && line.rfind("Note:", 0) != 0)
      std::cout << line << "\n";
}

}  // namespace robozoo::testing

/// Outside the namespace: runs the current test inside one and returns.
#define RUN_IN_PRIVATE_NETWORK(timeout_s, multicast_route)                                                           \
  if (!::robozoo::testing::inside_private_network()) {                                                               \
    const auto* info_ = ::testing::UnitTest::GetInstance()->current_test_info();                                     \
    return ::robozoo::testing::rerun_in_private_network(std::string(info_->test_suite_name()) + "." + info_->name(), \
                                                        timeout_s, multicast_route);                                 \
  }
