#pragma once
// Test support: a run extended to more generations against an uninterrupted
// one. The run messages logged before the extension say the generations the
// run was started for; everything else must be the same message for message.
// run_requested_as(log, n) rewrites every ROBOZOO_RUN of a log to n generations
// (run_t.generations and the configuration's "generations"), so that
// first_log_difference compares the rest.
#include <nlohmann/json.hpp>

#include "evolve/io/event_log.hpp"
#include "evolve/messages/build.hpp"
#include "evolve/messages/safe_decode.hpp"

namespace robozoo::testing {

inline LogContents run_requested_as(LogContents log, int32_t generations) {
  for (auto& r : log.records) {
    if (r.channel != kChannelRun) continue;
    run_t m;
    if (!safe_decode(r.data.data(), r.data.size(), m)) continue;  // compared (and reported) as it is
    m.generations = generations;
    nlohmann::json c = nlohmann::json::parse(m.config_json);
    c["generations"] = generations;
    m.config_json = c.dump();
    r.data = encode_message(m);
  }
  return log;
}

/// Generation messages in a log (count).
inline size_t count_run_generations(const LogContents& log) {
  size_t n = 0;
  for (const auto& r : log.records) n += r.channel == kChannelGeneration;
  return n;
}

}  // namespace robozoo::testing
