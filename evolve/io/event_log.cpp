#include "evolve/io/event_log.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
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
// data lengths (bytes).
constexpr int64_t kEventHeaderBytes = 4 + 8 + 8 + 4 + 4;
}  // namespace

LogContents read_event_log(const std::string& path) {
  struct stat st {};
  errno = 0;
  if (::stat(path.c_str(), &st) != 0) throw io_error(path, "cannot open the event log");
  lcm_eventlog_t* log = lcm_eventlog_create(path.c_str(), "r");
  if (!log) throw io_error(path, "cannot open the event log");
  LogContents out;
  out.file_bytes = st.st_size;
  while (lcm_eventlog_event_t* ev = lcm_eventlog_read_next_event(log)) {
    LogRecord r;
    r.eventnum = ev->eventnum;
    r.timestamp = ev->timestamp;
    r.channel.assign(ev->channel, static_cast<size_t>(ev->channellen));
    const auto* d = static_cast<const uint8_t*>(ev->data);
    r.data.assign(d, d + ev->datalen);
    out.event_bytes += kEventHeaderBytes + static_cast<int64_t>(r.channel.size()) + static_cast<int64_t>(r.data.size());
    out.records.push_back(std::move(r));
    lcm_eventlog_free_event(ev);
  }
  // LCM's reader stops at a cut last event with the file position at its end,
  // so the position cannot tell; the bytes the complete events take can.
  out.truncated = out.event_bytes != static_cast<int64_t>(st.st_size);
  lcm_eventlog_destroy(log);
  return out;
}

int64_t now_us() {
  return std::chrono::duration_cast<std::chrono::microseconds>(
             std::chrono::system_clock::now().time_since_epoch())
      .count();
}

}  // namespace robozoo
