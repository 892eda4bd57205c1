#pragma once
// Reading a robozoo log into runs: every event of the log (scan_event_log)
// through a MessageCollector, with clear errors for files that cannot be used.
// Used by robozoo-render, robozoo-view and robozoo-log.
#include <memory>
#include <string>
#include <vector>

#include "runlog/read/log_reader.hpp"
#include "runlog/read/message_collector.hpp"

namespace robozoo {

struct LoadOptions {
  bool allow_truncated = false;  ///< accept a log that ends inside an event (its complete events)
  bool keep_poses = true;        ///< keep pose streams (zoo sheets do not need them)
};

struct LoadedLog {
  std::string path;
  std::unique_ptr<MessageCollector> collector;  ///< one per log: run ids may repeat across logs
  bool truncated = false;                       ///< some bytes are no complete event (garbage or a cut end)
  std::vector<LogDamage> damage;                ///< where, as scan_event_log found it
  std::vector<const RunRecord*> runs() const;
};

/// Reads one log. Throws std::runtime_error naming the path when it is missing
/// or unreadable, holds bytes that are no complete event (unless allowed: the
/// events after garbage are read too), or holds no
/// ROBOZOO_RUN message. Messages that fail to decode are counted in the
/// collector's stats, not fatal.
LoadedLog load_log(const std::string& path, const LoadOptions& options = {});

/// One line about what a log held and what was rejected, e.g. for stderr.
std::string describe(const LoadedLog& log);

}  // namespace robozoo
