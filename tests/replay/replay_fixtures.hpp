#pragma once
// Test support for tests/replay: a log from a real short run (made once per
// test program, in process), and writing modified copies of a log.
#include <fcntl.h>  // tests/support/subprocess.hpp uses open()

#include <functional>
#include <memory>
#include <string>

#include "evolve/io/event_log.hpp"
#include "evolve/messages/build.hpp"
#include "evolve/messages/safe_decode.hpp"
#include "evolve/run/evaluator.hpp"
#include "evolve/run/evolution.hpp"
#include "tests/support/small_run.hpp"
#include "tests/support/subprocess.hpp"

namespace robozoo::testing {

/// The configuration of the small run: 4 generations of 24 robots, 400 steps
/// (still sends champions to the simulator, so the log holds trajectories).
using robozoo::testing::small_run_config;

/// Path of the small run's log, written on first use by Evolution with an
/// in-process evaluator (the same code robozoo-evolve runs).
inline const std::string& small_run_log() {
  static TempDir dir;
  static const std::string path = [] {
    const std::string p = dir / "small.lcmlog";
    InProcessEvaluator evaluator(small_run_config().eval);
    EvolveOptions o;
    o.log_path = p;
    Evolution evo(small_run_config(), o, evaluator);
    evo.run();
    return p;
  }();
  return path;
}

/// The small run's log, read once per test program.
inline const LogContents& small_log() {
  static const LogContents log = read_event_log(small_run_log());
  return log;
}

/// Writes `log`'s events to `path` with EventLogWriter, after `edit` (which may
/// change a record's bytes, or return false to drop it).
inline void write_log(const LogContents& log, const std::string& path,
                      const std::function<bool(size_t index, LogRecord& r)>& edit = {}) {
  EventLogWriter w = EventLogWriter::create(path);
  for (size_t i = 0; i < log.records.size(); ++i) {
    LogRecord r = log.records[i];
    if (edit && !edit(i, r)) continue;
    w.write(r.channel, r.data, r.timestamp);
  }
  w.sync();
}

/// Decodes a record as T (the test fails if it does not decode).
template <class T>
T decode_as(const LogRecord& r) {
  T m{};
  if (!safe_decode(r.data.data(), r.data.size(), m)) throw std::runtime_error("record does not decode");
  return m;
}

/// Index of the n-th record (0-based) on `channel`, or -1.
inline int64_t nth_on(const LogContents& log, const std::string& channel, size_t n = 0) {
  for (size_t i = 0; i < log.records.size(); ++i)
    if (log.records[i].channel == channel && n-- == 0) return static_cast<int64_t>(i);
  return -1;
}

}  // namespace robozoo::testing
