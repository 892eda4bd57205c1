#include "util/stop_signals.hpp"

#include <pthread.h>
#include <signal.h>
#include <unistd.h>

#include <cstring>
#include <stdexcept>
#include <system_error>

namespace robozoo {

namespace {
sigset_t stop_set() {
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGTERM);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGHUP);
  return set;
}

bool stop_signals_blocked() {
  sigset_t current;
  if (pthread_sigmask(SIG_BLOCK, nullptr, &current) != 0) return false;
  return sigismember(&current, SIGTERM) == 1 && sigismember(&current, SIGINT) == 1 &&
         sigismember(&current, SIGHUP) == 1;
}

void write_all(int fd, const std::string& text) {
  size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n <= 0) return;
    done += static_cast<size_t>(n);
  }
}
}  // namespace

void block_stop_signals() {
  const sigset_t set = stop_set();
  if (const int rc = pthread_sigmask(SIG_BLOCK, &set, nullptr))
    throw std::system_error(rc, std::generic_category(), "pthread_sigmask");
}

void unblock_stop_signals() {
  const sigset_t set = stop_set();
  pthread_sigmask(SIG_UNBLOCK, &set, nullptr);
}

std::function<bool()> poll_interrupts() {
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  if (const int rc = pthread_sigmask(SIG_BLOCK, &set, nullptr))
    throw std::system_error(rc, std::generic_category(), "pthread_sigmask");
  return [set] {
    timespec zero{0, 0};
    return sigtimedwait(&set, nullptr, &zero) > 0;
  };
}

StopWatcher::StopWatcher(std::string program) : StopWatcher(std::move(program), std::chrono::milliseconds(0)) {}

StopWatcher::StopWatcher(std::string program, std::chrono::milliseconds delay)
    : program_(std::move(program)), delay_(delay) {
  if (!stop_signals_blocked())
    throw std::logic_error("StopWatcher: block_stop_signals() must run before the watcher starts");
  thread_ = std::thread([this] { watch(); });
}

StopWatcher::~StopWatcher() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  stopped_.notify_all();
  pthread_kill(thread_.native_handle(), SIGTERM);  // wakes sigwait; `stopping_` says it is us
  thread_.join();
  unblock_stop_signals();
}

void StopWatcher::set_message(const std::string& message) {
  set_message_source([message] { return message; });
}

void StopWatcher::set_message_source(std::function<std::string()> source) {
  std::lock_guard<std::mutex> lock(mutex_);
  source_ = std::move(source);
}

void StopWatcher::watch() {
  const sigset_t set = stop_set();
  for (;;) {
    int sig = 0;
    if (sigwait(&set, &sig) != 0) continue;
    if (stopping_) return;
    if (delay_.count() > 0) {
      std::unique_lock<std::mutex> lock(mutex_);
      if (stopped_.wait_for(lock, delay_, [this] { return stopping_.load(); })) return;
    }
    if (program_.empty()) ::_exit(128 + sig);
    std::string line = program_ + ": stopped by signal " + std::to_string(sig);
    if (const char* name = strsignal(sig)) line += std::string(" (") + name + ")";
    {
      std::lock_guard<std::mutex> lock(mutex_);
      const std::string message = source_ ? source_() : "";
      if (!message.empty()) line += ": " + message;
    }
    write_all(STDERR_FILENO, line + "\n");
    ::_exit(128 + sig);
  }
}

}  // namespace robozoo
