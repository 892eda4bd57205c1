#pragma once
// Writing and reading LCM event logs (the format of lcm-logger, lcm-logplayer
// and lcm::LogFile). The log is the record of a run (DESIGN.md section 1).
#include <cstdint>
#include <string>
#include <vector>

#include <lcm/eventlog.h>

namespace robozoo {

class EventLogWriter {
 public:
  /// Creates a new, empty log at `path` (an existing file is replaced).
  /// Throws std::runtime_error naming the path on failure.
  static EventLogWriter create(const std::string& path);
  /// Re-opens a log written earlier, cuts it back to `bytes` (what a checkpoint
  /// recorded) and continues numbering events from `events`. Throws if the file
  /// is shorter than `bytes`.
  static EventLogWriter resume(const std::string& path, int64_t bytes, int64_t events);

  EventLogWriter(EventLogWriter&& o) noexcept;
  EventLogWriter& operator=(EventLogWriter&& o) noexcept;
  EventLogWriter(const EventLogWriter&) = delete;
  EventLogWriter& operator=(const EventLogWriter&) = delete;
  ~EventLogWriter();

  /// Appends one event; throws std::runtime_error on a write error.
  void write(const std::string& channel, const std::vector<uint8_t>& data, int64_t timestamp_us);
  /// Flushes to the operating system and to disk (fsync).
  void sync();
  /// Bytes written so far (after sync(): the file's size).
  int64_t bytes() const;
  /// Events written so far, counting those before a resume.
  int64_t events() const;
  const std::string& path() const { return path_; }

 private:
  EventLogWriter(std::string path, lcm_eventlog_t* log) : path_(std::move(path)), log_(log) {}
  std::string path_;
  lcm_eventlog_t* log_ = nullptr;
};

/// One event read back from a log.
struct LogRecord {
  int64_t eventnum = 0;
  int64_t timestamp = 0;  ///< (us)
  std::string channel;
  std::vector<uint8_t> data;
};

/// Reads every event of a log. Throws std::runtime_error naming the path if it
/// cannot be opened. LCM's reader resynchronises on the sync word after
/// garbage; a truncated last event ends the reading (reported in `truncated`).
struct LogContents {
  std::vector<LogRecord> records;
  bool truncated = false;   ///< the file ends inside an event
  int64_t file_bytes = 0;
};
LogContents read_event_log(const std::string& path);

/// Current time in microseconds since the Unix epoch (for utime fields).
int64_t now_us();

}  // namespace robozoo
