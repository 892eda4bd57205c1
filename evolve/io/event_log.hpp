#pragma once
// Writing and reading LCM event logs (the format of lcm-logger, lcm-logplayer
// and lcm::LogFile). The log is the record of a run (docs/method.md section 1).
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

/// Reads the complete events of a log, from the start up to the first cut or
/// damaged event, as LCM 1.3.1's reader does (bytes before the first sync word
/// are skipped; an event must be followed by the next sync word or the end of
/// the file; channel names are 1 to 999 bytes), but with every length checked
/// against the bytes left before anything is allocated: LCM's own reader
/// allocates whatever a damaged length field says (up to 2 GiB) and writes
/// through a null pointer when that allocation fails.
/// Throws std::runtime_error naming the path if it cannot be opened.
/// `truncated` says the events read do not account for every byte of the file:
/// it ends inside an event, or holds bytes that are not events. (robozoo-replay
/// reads damaged logs with its own reader that skips to the next event.)
struct LogContents {
  std::vector<LogRecord> records;
  bool truncated = false;  ///< the file holds bytes that are not complete events
  int64_t file_bytes = 0;
  int64_t event_bytes = 0;  ///< bytes the complete events take, headers included
};
LogContents read_event_log(const std::string& path);
/// The same reader on the bytes of a log already in memory.
LogContents parse_event_log(const uint8_t* data, size_t len);

/// The time stamp (us) of the event that ends exactly at byte `end` of the log
/// at `path`, found by searching back at most 16 MiB from there; -1 when there
/// is none (an empty log, an event larger than that, or bytes that are not
/// events). What a resumed run's next stamp must not precede.
int64_t timestamp_of_event_ending_at(const std::string& path, int64_t end);

/// Current time in microseconds since the Unix epoch (for utime fields).
int64_t now_us();

}  // namespace robozoo
