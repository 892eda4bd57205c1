#include "runlog/read/log_stream.hpp"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <vector>

namespace robozoo {

namespace {

[[noreturn]] void damaged(const std::string& path, LogDamage d, int64_t window_offset) {
  d.offset += window_offset;
  throw std::runtime_error(path + ": damaged: " + d.describe());
}

}  // namespace

int64_t for_each_event(const std::string& path, const std::function<void(const LogRecord&)>& on_event,
                       const LogStreamParams& params) {
  struct stat st {};
  errno = 0;
  if (::stat(path.c_str(), &st) != 0)
    throw std::runtime_error(path + ": cannot open the log (" + std::strerror(errno) + ")");
  if (!S_ISREG(st.st_mode)) throw std::runtime_error(path + ": not a regular file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot open the log");
  const int64_t size = st.st_size;
  size_t window = std::max<size_t>(params.window_bytes, 64);
  int64_t offset = 0, events = 0, last_eventnum = -1;
  std::vector<uint8_t> bytes;
  while (offset < size) {
    const int64_t want = std::min<int64_t>(static_cast<int64_t>(window), size - offset);
    const bool at_end = offset + want == size;
    bytes.resize(static_cast<size_t>(want));
    in.seekg(offset);
    in.read(reinterpret_cast<char*>(bytes.data()), want);
    if (in.gcount() != want) throw std::runtime_error(path + ": cannot read the log at byte " + std::to_string(offset));
    const ScannedLog w = scan_event_log_bytes(bytes);
    if (at_end && events == 0 && w.contents.records.empty())
      throw std::runtime_error(path + ": no LCM events in " + std::to_string(size) + " bytes: not an LCM log");
    // Damage before the window's last complete event is real; after it, it may
    // be an event the window cut, read again by the next window (unless at the end).
    for (const LogDamage& d : w.damage)
      if (at_end || d.offset < w.end_of_events) damaged(path, d, offset);
    if (w.contents.records.empty()) {
      if (at_end) {
        LogDamage d;
        d.kind = LogDamage::Kind::Garbage;
        d.bytes = want;
        d.after_event = last_eventnum;
        damaged(path, d, offset);
      }
      window *= 2;  // an event longer than the window
      continue;
    }
    for (size_t i = 0; i < w.contents.records.size(); ++i) {
      const LogRecord& r = w.contents.records[i];
      if (events > 0 && r.eventnum != last_eventnum + 1) {
        LogDamage d;
        d.kind = LogDamage::Kind::MissingEvents;
        d.offset = w.offsets[i];
        d.after_event = last_eventnum;
        d.next_event = r.eventnum;
        damaged(path, d, offset);
      }
      on_event(r);
      last_eventnum = r.eventnum;
      ++events;
    }
    offset += w.end_of_events;
  }
  return events;
}

}  // namespace robozoo
