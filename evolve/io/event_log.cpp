#include "evolve/io/event_log.hpp"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <chrono>
#include <cstring>
#include <stdexcept>

namespace robozoo {

namespace {
std::runtime_error io_error(const std::string& path, const std::string& what) {
  return std::runtime_error(path + ": " + what + (errno ? std::string(" (") + std::strerror(errno) + ")" : ""));
}
}  // namespace

EventLogWriter EventLogWriter::create(const std::string& path) {
  errno = 0;
  lcm_eventlog_t* log = lcm_eventlog_create(path.c_str(), "w");
  if (!log) throw io_error(path, "cannot create the event log");
  return EventLogWriter(path, log);
}

EventLogWriter EventLogWriter::resume(const std::string& path, int64_t bytes, int64_t events) {
  struct stat st {};
  errno = 0;
  if (::stat(path.c_str(), &st) != 0) throw io_error(path, "cannot resume the event log");
  if (st.st_size < bytes)
    throw std::runtime_error(path + ": the event log is shorter (" + std::to_string(st.st_size) +
                             " bytes) than its checkpoint says (" + std::to_string(bytes) + ")");
  if (::truncate(path.c_str(), bytes) != 0) throw io_error(path, "cannot cut the event log back");
  lcm_eventlog_t* log = lcm_eventlog_create(path.c_str(), "a");
  if (!log) throw io_error(path, "cannot reopen the event log");
  log->eventcount = events;
  return EventLogWriter(path, log);
}

EventLogWriter::EventLogWriter(EventLogWriter&& o) noexcept : path_(std::move(o.path_)), log_(o.log_) {
  o.log_ = nullptr;
}

EventLogWriter& EventLogWriter::operator=(EventLogWriter&& o) noexcept {
  if (this != &o) {
    if (log_) lcm_eventlog_destroy(log_);
    path_ = std::move(o.path_);
    log_ = o.log_;
    o.log_ = nullptr;
  }
  return *this;
}

EventLogWriter::~EventLogWriter() {
  if (log_) lcm_eventlog_destroy(log_);
}

void EventLogWriter::write(const std::string& channel, const std::vector<uint8_t>& data, int64_t timestamp_us) {
  lcm_eventlog_event_t ev{};
  ev.timestamp = timestamp_us;
  ev.channellen = static_cast<int32_t>(channel.size());
  ev.channel = const_cast<char*>(channel.c_str());
  ev.datalen = static_cast<int32_t>(data.size());
  ev.data = const_cast<uint8_t*>(data.data());
  errno = 0;
  if (lcm_eventlog_write_event(log_, &ev) != 0) throw io_error(path_, "write to the event log failed");
}

void EventLogWriter::sync() {
  errno = 0;
  if (std::fflush(log_->f) != 0 || ::fsync(fileno(log_->f)) != 0) throw io_error(path_, "cannot flush the event log");
}

int64_t EventLogWriter::bytes() const { return static_cast<int64_t>(std::ftell(log_->f)); }
int64_t EventLogWriter::events() const { return log_->eventcount; }

namespace {
// An LCM log event's header: sync word, event number, timestamp, channel and
// data lengths (bytes), big-endian.
constexpr int64_t kEventHeaderBytes = 4 + 8 + 8 + 4 + 4;
constexpr uint32_t kSyncWord = 0xEDA1DA01;
constexpr int32_t kMaxChannelBytes = 999;  // LCM's limit

uint64_t big_endian(const uint8_t* p, int n) {
  uint64_t v = 0;
  for (int i = 0; i < n; ++i) v = (v << 8) | p[i];
  return v;
}

// The file mapped read-only (nothing mapped for an empty file).
class MappedFile {
 public:
  explicit MappedFile(const std::string& path) {
    errno = 0;
    fd_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd_ < 0) throw io_error(path, "cannot open the event log");
    struct stat st {};
    if (::fstat(fd_, &st) != 0) {
      ::close(fd_);
      throw io_error(path, "cannot open the event log");
    }
    if (!S_ISREG(st.st_mode)) {
      ::close(fd_);
      errno = 0;
      throw io_error(path, "not a regular file");
    }
    len_ = static_cast<size_t>(st.st_size);
    if (len_ > 0) {
      void* p = ::mmap(nullptr, len_, PROT_READ, MAP_PRIVATE, fd_, 0);
      if (p == MAP_FAILED) {
        ::close(fd_);
        throw io_error(path, "cannot read the event log");
      }
      data_ = static_cast<const uint8_t*>(p);
    }
  }
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;
  ~MappedFile() {
    if (data_) ::munmap(const_cast<uint8_t*>(data_), len_);
    ::close(fd_);
  }
  const uint8_t* data() const { return data_; }
  size_t size() const { return len_; }

 private:
  int fd_ = -1;
  const uint8_t* data_ = nullptr;
  size_t len_ = 0;
};
}  // namespace

LogContents parse_event_log(const uint8_t* data, size_t len) {
  LogContents out;
  out.file_bytes = static_cast<int64_t>(len);
  const int64_t n = static_cast<int64_t>(len);
  int64_t pos = 0;
  // Like LCM's reader, look for the first sync word; after that, every event
  // must start right where the previous one ended.
  uint32_t window = 0;
  while (pos < n) {
    window = (window << 8) | data[pos++];
    if (window == kSyncWord) break;
  }
  if (window != kSyncWord) {
    out.truncated = out.file_bytes != 0;
    return out;
  }
  pos -= 4;
  while (pos + kEventHeaderBytes <= n && big_endian(data + pos, 4) == kSyncWord) {
    const uint8_t* h = data + pos + 4;
    const auto eventnum = static_cast<int64_t>(big_endian(h, 8));
    const auto timestamp = static_cast<int64_t>(big_endian(h + 8, 8));
    const auto channellen = static_cast<int32_t>(big_endian(h + 16, 4));
    const auto datalen = static_cast<int32_t>(big_endian(h + 20, 4));
    if (channellen < 1 || channellen > kMaxChannelBytes || datalen < 0) break;
    const int64_t left = n - pos - kEventHeaderBytes;
    if (int64_t(channellen) + int64_t(datalen) > left) break;  // cut: checked before allocating
    const int64_t end = pos + kEventHeaderBytes + channellen + datalen;
    // LCM's reader drops an event not followed by the next sync word (when
    // four more bytes are there to tell).
    if (end + 4 <= n && big_endian(data + end, 4) != kSyncWord) break;
    LogRecord r;
    r.eventnum = eventnum;
    r.timestamp = timestamp;
    const uint8_t* c = data + pos + kEventHeaderBytes;
    r.channel.assign(reinterpret_cast<const char*>(c), static_cast<size_t>(channellen));
    r.data.assign(c + channellen, c + channellen + datalen);
    out.event_bytes += end - pos;
    out.records.push_back(std::move(r));
    pos = end;
  }
  out.truncated = out.event_bytes != out.file_bytes;
  return out;
}

LogContents read_event_log(const std::string& path) {
  MappedFile f(path);
  return parse_event_log(f.data(), f.size());
}

int64_t timestamp_of_event_ending_at(const std::string& path, int64_t end) {
  constexpr int64_t kWindow = 16 << 20;
  constexpr int64_t kHeader = 4 + 8 + 8 + 4 + 4;  // sync, eventnum, timestamp, channellen, datalen
  if (end < kHeader) return -1;
  const int64_t from = std::max<int64_t>(0, end - kWindow);
  std::vector<uint8_t> b(static_cast<size_t>(end - from));
  FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) return -1;
  const bool ok =
      std::fseek(f, static_cast<long>(from), SEEK_SET) == 0 && std::fread(b.data(), 1, b.size(), f) == b.size();
  std::fclose(f);
  if (!ok) return -1;
  const auto be = [&](int64_t at, int n) {
    uint64_t v = 0;
    for (int i = 0; i < n; ++i) v = (v << 8) | b[static_cast<size_t>(at + i)];
    return v;
  };
  for (int64_t p = static_cast<int64_t>(b.size()) - kHeader; p >= 0; --p) {
    if (be(p, 4) != kSyncWord) continue;
    const int64_t channel_len = static_cast<int64_t>(be(p + 20, 4)), data_len = static_cast<int64_t>(be(p + 24, 4));
    if (p + kHeader + channel_len + data_len == static_cast<int64_t>(b.size()))
      return static_cast<int64_t>(be(p + 12, 8));
  }
  return -1;
}

int64_t now_us() {
  return std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}

}  // namespace robozoo
