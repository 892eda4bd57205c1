#pragma once
// Reading an LCM event log (lcm-logger's format, the one robozoo-evolve writes)
// and saying exactly where it is damaged: the reader behind every program that
// reads robozoo logs (render, replay, view, log).
//
// LCM's own reader (lcm_eventlog_read_next_event) says nothing about what it
// skipped: LCM 1.3.1 stops at the first garbage that follows an event ("Invalid
// header after log data"), and trusts the length fields of a header it finds
// (evolve's read_event_log keeps LCM's stopping rule but checks every length).
// This reader gives the same
// events for an intact log, resynchronises on the sync word after garbage,
// checks every header (channel length 1-999, data length >= 0 and inside the
// file) before it allocates, and reports each skipped byte range, a cut last
// event and jumps in the event numbers.
#include <cstdint>
#include <string>
#include <vector>

#include "evolve/io/event_log.hpp"

namespace robozoo {

/// One place where the log is not a clean sequence of events.
struct LogDamage {
  enum class Kind { Garbage, Truncated, MissingEvents };
  Kind kind = Kind::Garbage;
  int64_t offset = 0;            ///< byte offset in the file where it starts (bytes)
  int64_t bytes = 0;             ///< bytes skipped (Garbage, Truncated), 0 for MissingEvents (bytes)
  int64_t after_event = -1;      ///< event number of the last good event before it, -1 if none
  int64_t next_event = -1;       ///< MissingEvents: the event number that follows after_event
  std::string describe() const;  ///< one sentence, with offsets and event numbers
};

struct ScannedLog {
  LogContents contents;           ///< the events that could be read, in file order; event_bytes is
                                  ///< what they take, truncated says the last event is cut
  std::vector<int64_t> offsets;   ///< byte offset of each event's sync word (parallel to records)
  std::vector<LogDamage> damage;  ///< in file order; empty for an intact log
  int64_t end_of_events = 0;      ///< byte offset just after the last complete event (bytes)
  /// Bytes of the file that are no complete event (garbage and a cut last event).
  int64_t damaged_bytes() const { return contents.file_bytes - contents.event_bytes; }
};

/// The LCM log sync word, big-endian on disk.
inline constexpr uint32_t kLcmLogSyncWord = 0xEDA1DA01u;

/// Parses log bytes already in memory.
ScannedLog scan_event_log_bytes(const std::vector<uint8_t>& bytes);
/// Reads and parses the file at `path`; throws std::runtime_error naming the path
/// when it cannot be read.
ScannedLog scan_event_log(const std::string& path);
/// The same for the bytes from `offset` to the end (a log that grows: offsets,
/// damage and end_of_events are counted from `offset`).
ScannedLog scan_event_log_from(const std::string& path, int64_t offset);

}  // namespace robozoo
