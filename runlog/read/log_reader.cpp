#include "runlog/read/log_reader.hpp"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>

namespace robozoo {

namespace {

constexpr int64_t kHeaderBytes = 4 + 8 + 8 + 4 + 4;  // sync, eventnum, timestamp, channellen, datalen
constexpr int32_t kMaxChannelLength = 999;           // LCM's own limit for log channel names

uint32_t be32(const uint8_t* p) {
  return (uint32_t(p[0]) << 24) | (uint32_t(p[1]) << 16) | (uint32_t(p[2]) << 8) | uint32_t(p[3]);
}
uint64_t be64(const uint8_t* p) { return (uint64_t(be32(p)) << 32) | be32(p + 4); }

/// Offset of the first sync word at or after `from`, or -1.
int64_t find_sync(const std::vector<uint8_t>& b, int64_t from) {
  const int64_t n = static_cast<int64_t>(b.size());
  for (int64_t i = from; i + 4 <= n; ++i)
    if (b[i] == 0xED && b[i + 1] == 0xA1 && b[i + 2] == 0xDA && b[i + 3] == 0x01) return i;
  return -1;
}

}  // namespace

std::string LogDamage::describe() const {
  const std::string after = after_event < 0 ? "before the first event" : "after event " + std::to_string(after_event);
  switch (kind) {
    case Kind::Garbage:
      return std::to_string(bytes) + " bytes that are no event at byte offset " + std::to_string(offset) + " (" +
             after + "), skipped up to the next sync word";
    case Kind::Truncated:
      return "the log ends inside an event: its last " + std::to_string(bytes) + " bytes, from byte offset " +
             std::to_string(offset) + " (" + after + "), are cut";
    case Kind::MissingEvents:
      if (next_event > after_event)
        return "event numbers jump from " + std::to_string(after_event) + " to " + std::to_string(next_event) +
               " at byte offset " + std::to_string(offset) + ": " + std::to_string(next_event - after_event - 1) +
               " events missing";
      return "event numbers go back from " + std::to_string(after_event) + " to " + std::to_string(next_event) +
             " at byte offset " + std::to_string(offset);
  }
  return "";
}

ScannedLog scan_event_log_bytes(const std::vector<uint8_t>& b) {
  ScannedLog out;
  out.contents.file_bytes = static_cast<int64_t>(b.size());
  const int64_t n = static_cast<int64_t>(b.size());
  int64_t pos = 0;
  int64_t last_eventnum = -1;
  bool have_event = false;
  int64_t garbage_from = -1;  // start of a run of skipped bytes not yet reported
  auto flush_garbage = [&](int64_t until) {
    if (garbage_from >= 0 && until > garbage_from) {
      LogDamage d;
      d.kind = LogDamage::Kind::Garbage;
      d.offset = garbage_from;
      d.bytes = until - garbage_from;
      d.after_event = have_event ? last_eventnum : -1;
      out.damage.push_back(d);
    }
    garbage_from = -1;
  };
  while (pos < n) {
    const int64_t s = find_sync(b, pos);
    if (s < 0) {  // bytes after the last event that hold no sync word
      if (garbage_from < 0) garbage_from = pos;
      flush_garbage(n);
      break;
    }
    if (s > pos && garbage_from < 0) garbage_from = pos;
    bool valid = s + kHeaderBytes <= n;
    int32_t channellen = 0, datalen = 0;
    if (valid) {
      channellen = static_cast<int32_t>(be32(&b[s + 20]));
      datalen = static_cast<int32_t>(be32(&b[s + 24]));
      valid = channellen >= 1 && channellen <= kMaxChannelLength && datalen >= 0 &&
              s + kHeaderBytes + channellen + static_cast<int64_t>(datalen) <= n;
    }
    if (!valid) {
      if (find_sync(b, s + 1) < 0) {  // nothing readable follows: a cut last event
        flush_garbage(s);
        LogDamage d;
        d.kind = LogDamage::Kind::Truncated;
        d.offset = s;
        d.bytes = n - s;
        d.after_event = have_event ? last_eventnum : -1;
        out.damage.push_back(d);
        out.contents.truncated = true;
        break;
      }
      if (garbage_from < 0) garbage_from = s;  // a damaged header: skip its sync word
      pos = s + 1;
      continue;
    }
    flush_garbage(s);
    LogRecord r;
    r.eventnum = static_cast<int64_t>(be64(&b[s + 4]));
    r.timestamp = static_cast<int64_t>(be64(&b[s + 12]));
    const auto* ch = reinterpret_cast<const char*>(&b[s + kHeaderBytes]);
    r.channel.assign(ch, static_cast<size_t>(channellen));
    const auto data = b.begin() + s + kHeaderBytes + channellen;
    r.data.assign(data, data + datalen);
    if (have_event && r.eventnum != last_eventnum + 1) {
      LogDamage d;
      d.kind = LogDamage::Kind::MissingEvents;
      d.offset = s;
      d.after_event = last_eventnum;
      d.next_event = r.eventnum;
      out.damage.push_back(d);
    }
    last_eventnum = r.eventnum;
    have_event = true;
    out.contents.event_bytes += kHeaderBytes + channellen + datalen;
    out.contents.records.push_back(std::move(r));
    out.offsets.push_back(s);
    pos = s + kHeaderBytes + channellen + datalen;
    out.end_of_events = pos;
  }
  return out;
}

ScannedLog scan_event_log(const std::string& path) { return scan_event_log_from(path, 0); }

ScannedLog scan_event_log_from(const std::string& path, int64_t offset) {
  struct stat st {};
  errno = 0;
  if (::stat(path.c_str(), &st) != 0)
    throw std::runtime_error(path + ": cannot open the log (" + std::strerror(errno) + ")");
  if (!S_ISREG(st.st_mode)) throw std::runtime_error(path + ": not a regular file");
  if (offset < 0 || offset > st.st_size)
    throw std::runtime_error(path + ": is " + std::to_string(st.st_size) + " bytes, shorter than before (" +
                             std::to_string(offset) + "): not the same log any more");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot open the log");
  in.seekg(offset);
  std::vector<uint8_t> bytes(static_cast<size_t>(st.st_size - offset));
  in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  if (in.gcount() != static_cast<std::streamsize>(bytes.size()))
    throw std::runtime_error(path + ": cannot read the log (" + std::to_string(in.gcount()) + " of " +
                             std::to_string(bytes.size()) + " bytes)");
  return scan_event_log_bytes(bytes);
}

}  // namespace robozoo
