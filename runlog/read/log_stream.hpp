#pragma once
// A log read event by event in bounded memory (robozoo-log export of large
// logs): windows of the file through the shared reader (scan_event_log_bytes),
// each window's complete events handed on, the next window starting after the
// last of them. Damage is what scan_event_log would report, with file offsets.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>

#include "runlog/read/log_reader.hpp"

namespace robozoo {

struct LogStreamParams {
  size_t window_bytes = size_t{4} << 20;  ///< bytes read at a time; doubled while one event does not fit (bytes)
};

/// Calls `on_event` for every event of the log at `path`, in file order, and
/// returns how many. Throws std::runtime_error naming the path when the file
/// cannot be read or holds no event at all (not an LCM log), and at the first damage (garbage, a cut last event, missing
/// event numbers), with its description; events before it were handed on.
int64_t for_each_event(const std::string& path, const std::function<void(const LogRecord&)>& on_event,
                       const LogStreamParams& params = {});

}  // namespace robozoo
