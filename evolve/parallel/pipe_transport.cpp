#include "evolve/parallel/pipe_transport.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <system_error>
#include <thread>

namespace robozoo {
namespace {

using Clock = std::chrono::steady_clock;

constexpr size_t kReadChunk = 64 * 1024;
/// How long a worker whose socket reached end-of-file may take to finish exiting
/// before it is killed (it closed its socket, so it is leaving or misbehaving).
constexpr double kExitWaitS = 1.0;

// Exit codes of a worker child.
constexpr int kExitNormal = 0;
constexpr int kExitProtocol = 3;
constexpr int kExitException = 4;
constexpr int kExitIo = 5;

std::string describe_status(int status) {
  if (WIFEXITED(status)) {
    const int code = WEXITSTATUS(status);
    std::string s = "exited with status " + std::to_string(code);
    if (code == kExitProtocol) s += " (protocol error in the worker)";
    if (code == kExitException) s += " (unexpected exception in the worker loop)";
    if (code == kExitIo) s += " (I/O error in the worker)";
    return s;
  }
  if (WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    std::string s = "killed by signal " + std::to_string(sig);
    if (const char* name = strsignal(sig)) s += std::string(" (") + name + ")";
    if (WCOREDUMP(status)) s += ", core dumped";
    return s;
  }
  return "ended with wait status " + std::to_string(status);
}

/// waitpid, retried on EINTR; returns the pid, 0 (WNOHANG, still running) or -1.
pid_t wait_for(pid_t pid, int* status, int options) {
  for (;;) {
    const pid_t r = ::waitpid(pid, status, options);
    if (r >= 0 || errno != EINTR) return r;
  }
}

/// Kills and reaps a child; tolerates one that is already gone.
void kill_and_reap(pid_t pid) {
  if (pid <= 0) return;
  ::kill(pid, SIGKILL);
  int status = 0;
  wait_for(pid, &status, 0);
}

void close_fd(int& fd) {
  if (fd >= 0) ::close(fd);
  fd = -1;
}

bool write_all(int fd, const Bytes& data) {
  size_t done = 0;
  while (done < data.size()) {
    const ssize_t n = ::send(fd, data.data() + done, data.size() - done, MSG_NOSIGNAL);
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    done += static_cast<size_t>(n);
  }
  return true;
}

/// The worker child: never returns.
[[noreturn]] void child_main(int fd, const std::vector<int>& foreign_fds, const WorkFn& fn,
                             const PipeTransportParams& params, pid_t parent) {
  // Die with the parent, even if it is killed without a chance to clean up.
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (::getppid() != parent) ::_exit(kExitNormal);

  // Ctrl-C is the parent's to handle; other signals act as they do by default.
  struct sigaction sa;
  std::memset(&sa, 0, sizeof sa);
  sigemptyset(&sa.sa_mask);
  sa.sa_handler = SIG_IGN;
  ::sigaction(SIGINT, &sa, nullptr);
  sa.sa_handler = SIG_DFL;
  for (int sig : {SIGTERM, SIGHUP, SIGQUIT, SIGPIPE, SIGCHLD, SIGUSR1, SIGUSR2, SIGALRM})
    ::sigaction(sig, &sa, nullptr);
  sigset_t none;
  sigemptyset(&none);
  ::sigprocmask(SIG_SETMASK, &none, nullptr);

  // No other worker's socket, nor (by default) any other descriptor of the parent.
  for (int other : foreign_fds) ::close(other);
  if (params.close_inherited_fds) {
    if (fd != 3) {
      if (::dup2(fd, 3) < 0) ::_exit(kExitIo);
      ::close(fd);
      fd = 3;
    }
    if (::close_range(4, ~0u, 0) != 0) {
      const long max_fd = std::min(::sysconf(_SC_OPEN_MAX), 65536L);
      for (long i = 4; i < max_fd; ++i) ::close(static_cast<int>(i));
    }
  }

  int code = kExitNormal;
  try {
    FrameReader reader(params.max_body_bytes);
    Bytes buf(kReadChunk);
    for (bool running = true; running;) {
      while (auto frame = reader.next()) {
        std::optional<Bytes> reply = serve_frame(fn, std::move(*frame));
        if (!reply) {  // Shutdown
          running = false;
          break;
        }
        if (!write_all(fd, *reply)) {  // the parent went away
          running = false;
          break;
        }
      }
      if (!running) break;
      const ssize_t n = ::read(fd, buf.data(), buf.size());
      if (n == 0) break;  // the parent closed our socket: done
      if (n < 0) {
        if (errno == EINTR) continue;
        code = errno == ECONNRESET ? kExitNormal : kExitIo;
        break;
      }
      reader.feed(buf.data(), static_cast<size_t>(n));
    }
  } catch (const ProtocolError&) {
    code = kExitProtocol;
  } catch (...) {
    code = kExitException;
  }
  std::fflush(nullptr);
  ::_exit(code);
}

}  // namespace

PipeTransport::PipeTransport(int workers, WorkFn fn, PipeTransportParams params) : fn_(std::move(fn)), params_(params) {
  if (workers < 1) throw std::invalid_argument("PipeTransport: need at least 1 worker, got " + std::to_string(workers));
  if (!fn_) throw std::invalid_argument("PipeTransport: empty work function");
  if (!(params_.shutdown_grace_s >= 0.0) || !std::isfinite(params_.shutdown_grace_s))
    throw std::invalid_argument("PipeTransport: shutdown_grace_s must be finite and >= 0");
  slots_.resize(static_cast<size_t>(workers));
  for (auto& s : slots_) s.reader = FrameReader(params_.max_body_bytes);
  try {
    for (int w = 0; w < workers; ++w) spawn(w);
  } catch (...) {
    for (int w = 0; w < workers; ++w) discard(w);
    throw;
  }
}

PipeTransport::~PipeTransport() {
  // Closing a socket is a worker's signal to finish: it reads end-of-file and exits.
  for (auto& s : slots_) close_fd(s.fd);
  const auto deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                           std::chrono::duration<double>(params_.shutdown_grace_s));
  for (;;) {
    bool waiting = false;
    for (auto& s : slots_) {
      if (s.pid <= 0) continue;
      int status = 0;
      const pid_t r = wait_for(s.pid, &status, WNOHANG);
      if (r == 0)
        waiting = true;
      else
        s.pid = -1;  // reaped, or not our child any more (ECHILD)
    }
    if (!waiting || Clock::now() >= deadline) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  for (auto& s : slots_) {  // stragglers: still busy with a job, or hung
    kill_and_reap(s.pid);
    s.pid = -1;
  }
}

void PipeTransport::check(int w) const {
  if (w < 0 || w >= size())
    throw std::out_of_range("PipeTransport: no worker " + std::to_string(w) + " (have " + std::to_string(size()) + ")");
}

pid_t PipeTransport::pid(int w) const {
  check(w);
  return slots_[static_cast<size_t>(w)].pid;
}

void PipeTransport::spawn(int w) {
  Slot& slot = slots_[static_cast<size_t>(w)];
  std::vector<int> foreign;  // allocated before fork: the child only closes them
  for (const auto& s : slots_)
    if (s.fd >= 0) foreign.push_back(s.fd);

  int sv[2];
  if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, sv) != 0)
    throw std::system_error(errno, std::generic_category(), "PipeTransport: socketpair");
  foreign.push_back(sv[0]);
  std::fflush(nullptr);  // else the child would inherit, and might write, buffered output
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) {
    const int err = errno;
    ::close(sv[0]);
    ::close(sv[1]);
    throw std::system_error(err, std::generic_category(), "PipeTransport: fork");
  }
  if (pid == 0) child_main(sv[1], foreign, fn_, params_, parent);

  ::close(sv[1]);
  const int flags = ::fcntl(sv[0], F_GETFL);
  if (flags < 0 || ::fcntl(sv[0], F_SETFL, flags | O_NONBLOCK) < 0) {
    const int err = errno;
    ::close(sv[0]);
    kill_and_reap(pid);
    throw std::system_error(err, std::generic_category(), "PipeTransport: fcntl");
  }
  slot.pid = pid;
  slot.fd = sv[0];
  slot.out.clear();
  slot.out_sent = 0;
  slot.reader.clear();
}

void PipeTransport::discard(int w) {
  Slot& slot = slots_[static_cast<size_t>(w)];
  close_fd(slot.fd);
  kill_and_reap(slot.pid);
  slot.pid = -1;
  slot.out.clear();
  slot.out_sent = 0;
  slot.reader.clear();
  for (auto it = events_.begin(); it != events_.end();) it = it->worker == w ? events_.erase(it) : it + 1;
}

void PipeTransport::bury(int w, const std::string& why, bool kill_now) {
  Slot& slot = slots_[static_cast<size_t>(w)];
  // Killed before its socket closes: a worker that reads end-of-file exits on
  // its own, and would be reported as having exited normally.
  if (kill_now && slot.pid > 0) ::kill(slot.pid, SIGKILL);
  close_fd(slot.fd);
  slot.out.clear();
  slot.out_sent = 0;
  slot.reader.clear();
  std::string reason = why;
  if (slot.pid > 0) {
    int status = 0;
    pid_t r = 0;
    if (!kill_now) {
      const auto deadline =
          Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(kExitWaitS));
      while ((r = wait_for(slot.pid, &status, WNOHANG)) == 0 && Clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::microseconds(200));
      if (r == 0) {
        ::kill(slot.pid, SIGKILL);
        reason += " (did not exit after closing its socket; killed)";
      }
    }
    if (r == 0) r = wait_for(slot.pid, &status, 0);
    reason += r > 0 ? ": " + describe_status(status) : ": exit status unavailable";
  }
  slot.pid = -1;
  WorkerEvent e;
  e.kind = WorkerEvent::Kind::Died;
  e.worker = w;
  e.reason = "worker " + std::to_string(w) + " " + reason;
  events_.push_back(std::move(e));
}

void PipeTransport::flush_out(int w) {
  Slot& slot = slots_[static_cast<size_t>(w)];
  while (slot.fd >= 0 && slot.out_sent < slot.out.size()) {
    const ssize_t n =
        ::send(slot.fd, slot.out.data() + slot.out_sent, slot.out.size() - slot.out_sent, MSG_NOSIGNAL | MSG_DONTWAIT);
    if (n >= 0) {
      slot.out_sent += static_cast<size_t>(n);
      continue;
    }
    if (errno == EINTR) continue;
    if (errno == EAGAIN || errno == EWOULDBLOCK) return;
    if (errno == EPIPE || errno == ECONNRESET) {
      bury(w, "lost its connection", false);
    } else {
      bury(w, std::string("could not be written to (") + std::strerror(errno) + ")", true);
    }
    return;
  }
  if (slot.out_sent == slot.out.size()) {
    slot.out.clear();
    slot.out_sent = 0;
  }
}

void PipeTransport::read_from(int w) {
  Slot& slot = slots_[static_cast<size_t>(w)];
  uint8_t buf[kReadChunk];
  while (slot.fd >= 0) {
    const ssize_t n = ::read(slot.fd, buf, sizeof buf);
    if (n == 0) {
      bury(w, "closed its connection", false);
      return;
    }
    if (n < 0) {
      if (errno == EINTR) continue;
      if (errno == EAGAIN || errno == EWOULDBLOCK) return;
      if (errno == ECONNRESET)
        bury(w, "lost its connection", false);
      else
        bury(w, std::string("could not be read from (") + std::strerror(errno) + ")", true);
      return;
    }
    slot.reader.feed(buf, static_cast<size_t>(n));
    try {
      while (auto frame = slot.reader.next()) {
        WorkerEvent e;
        e.kind = WorkerEvent::Kind::Result;
        e.worker = w;
        e.result = result_from_frame(std::move(*frame));
        events_.push_back(std::move(e));
      }
    } catch (const ProtocolError& err) {
      bury(w, std::string("broke the protocol (") + err.what() + ")", true);
      return;
    }
  }
}

bool PipeTransport::send(int w, const Job& job) {
  check(w);
  Slot& slot = slots_[static_cast<size_t>(w)];
  if (slot.fd < 0) return false;  // dead; its Died event is pending
  const bool idle_before = slot.out_sent == 0 && slot.out.empty();
  Bytes frame = encode_job(job);
  if (slot.out.empty())
    slot.out = std::move(frame);
  else
    slot.out.insert(slot.out.end(), frame.begin(), frame.end());
  flush_out(w);
  // Died before taking a single byte of this job: nothing was delivered.
  if (slot.fd < 0 && idle_before) return false;
  return true;
}

std::optional<WorkerEvent> PipeTransport::receive(double timeout_s) {
  if (std::isnan(timeout_s)) throw std::invalid_argument("PipeTransport::receive: NaN timeout");
  const auto start = Clock::now();
  const double clipped = std::min(std::max(timeout_s, 0.0), 1e6);
  const auto deadline = start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(clipped));
  std::vector<pollfd> fds;
  std::vector<int> owner;
  for (bool first = true;; first = false) {
    if (!events_.empty()) {
      WorkerEvent e = std::move(events_.front());
      events_.pop_front();
      return e;
    }
    const auto now = Clock::now();
    if (!first && now >= deadline) return std::nullopt;  // poll at least once
    fds.clear();
    owner.clear();
    for (int w = 0; w < size(); ++w) {
      const Slot& s = slots_[static_cast<size_t>(w)];
      if (s.fd < 0) continue;
      short ev = POLLIN;
      if (s.out_sent < s.out.size()) ev |= POLLOUT;
      fds.push_back(pollfd{s.fd, ev, 0});
      owner.push_back(w);
    }
    const double left = std::chrono::duration<double>(deadline - now).count();
    const int ms = left <= 0.0 ? 0 : static_cast<int>(std::min(std::ceil(left * 1000.0), double(INT_MAX)));
    const int r = ::poll(fds.data(), fds.size(), ms);
    if (r < 0) {
      if (errno == EINTR) continue;
      throw std::system_error(errno, std::generic_category(), "PipeTransport: poll");
    }
    for (size_t i = 0; i < fds.size(); ++i) {
      const int w = owner[i];
      if (fds[i].revents & POLLOUT) flush_out(w);
      if (fds[i].revents & (POLLIN | POLLHUP | POLLERR)) read_from(w);
      if (fds[i].revents & POLLNVAL)
        throw std::logic_error("PipeTransport: worker " + std::to_string(w) + "'s socket is invalid");
    }
    if (r == 0 && events_.empty()) return std::nullopt;  // timed out
  }
}

void PipeTransport::restart(int w) {
  check(w);
  discard(w);
  spawn(w);
}

}  // namespace robozoo
