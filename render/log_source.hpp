#pragma once
// Reading robozoo logs for rendering: every event of an LCM log through a
// MessageCollector, with clear errors for files that cannot be used.
#include <memory>
#include <string>
#include <vector>

#include "render/message_collector.hpp"

namespace robozoo::render {

struct LoadOptions {
  bool allow_truncated = false;  ///< accept a log that ends inside an event (its complete events)
  bool keep_poses = true;        ///< keep pose streams (zoo sheets do not need them)
};

struct LoadedLog {
  std::string path;
  std::unique_ptr<MessageCollector> collector;  ///< one per log: run ids may repeat across logs
  bool truncated = false;
  std::vector<const RunRecord*> runs() const;
};

/// Reads one log. Throws std::runtime_error naming the path when it is missing
/// or unreadable, ends inside an event (unless allowed), or holds no
/// ROBOZOO_RUN message. Messages that fail to decode are counted in the
/// collector's stats, not fatal.
LoadedLog load_log(const std::string& path, const LoadOptions& options = {});

/// One line about what a log held and what was rejected, e.g. for stderr.
std::string describe(const LoadedLog& log);

}  // namespace robozoo::render
