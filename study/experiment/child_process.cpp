#include "study/experiment/child_process.hpp"

#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <stdexcept>

namespace robozoo {

namespace {

int decode_status(int st) { return WIFEXITED(st) ? WEXITSTATUS(st) : 128 + WTERMSIG(st); }

// waitpid without blocking; true with `status` when the child has ended.
bool reap(pid_t pid, int& status) {
  int st = 0;
  pid_t r;
  while ((r = ::waitpid(pid, &st, WNOHANG)) < 0 && errno == EINTR) {
  }
  if (r == pid) {
    status = decode_status(st);
    return true;
  }
  if (r < 0) {  // not our child any more (already reaped): report it as gone
    status = 255;
    return true;
  }
  return false;
}

}  // namespace

SignalBlock::SignalBlock() {
  sigemptyset(&set_);
  for (int s : {SIGINT, SIGTERM, SIGHUP, SIGCHLD}) sigaddset(&set_, s);
  if (::sigprocmask(SIG_BLOCK, &set_, &old_) != 0) throw std::runtime_error("sigprocmask failed");
}

SignalBlock::~SignalBlock() { ::sigprocmask(SIG_SETMASK, &old_, nullptr); }

pid_t spawn_child(const std::vector<std::string>& argv, const std::string& output_path) {
  if (argv.empty()) throw std::invalid_argument("spawn_child: no program");
  const int out = ::open(output_path.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (out < 0) throw std::runtime_error("cannot open " + output_path + ": " + std::strerror(errno));
  int errpipe[2];  // the child reports a failed exec through it
  if (::pipe2(errpipe, O_CLOEXEC) != 0) {
    ::close(out);
    throw std::runtime_error("pipe failed");
  }
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(out);
    ::close(errpipe[0]);
    ::close(errpipe[1]);
    throw std::runtime_error(std::string("fork failed: ") + std::strerror(errno));
  }
  if (pid == 0) {
    ::setpgid(0, 0);
    ::prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (::getppid() != parent) ::_exit(143);  // the driver died before prctl
    sigset_t none;
    sigemptyset(&none);
    ::sigprocmask(SIG_SETMASK, &none, nullptr);
    const int in = ::open("/dev/null", O_RDONLY);
    if (in >= 0) ::dup2(in, 0);
    ::dup2(out, 1);
    ::dup2(out, 2);
    std::vector<char*> args;
    for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    ::execv(args[0], args.data());
    const int e = errno;
    (void)!::write(errpipe[1], &e, sizeof e);
    ::_exit(127);
  }
  ::setpgid(pid, pid);  // also from the parent, so the group exists before any kill
  ::close(out);
  ::close(errpipe[1]);
  int e = 0;
  ssize_t n;
  while ((n = ::read(errpipe[0], &e, sizeof e)) < 0 && errno == EINTR) {
  }
  ::close(errpipe[0]);
  if (n == static_cast<ssize_t>(sizeof e)) {
    int st;
    ::waitpid(pid, &st, 0);
    throw std::runtime_error("cannot run " + argv[0] + ": " + std::strerror(e));
  }
  return pid;
}

ChildEvent wait_child(const SignalBlock& block, pid_t pid, double timeout_s) {
  ChildEvent ev;
  if (reap(pid, ev.status)) {
    ev.kind = ChildEvent::Exited;
    return ev;
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  for (;;) {
    const double left = std::chrono::duration<double>(deadline - std::chrono::steady_clock::now()).count();
    if (left <= 0) return ev;
    timespec ts{};
    ts.tv_sec = static_cast<time_t>(left);
    ts.tv_nsec = static_cast<long>((left - std::floor(left)) * 1e9);
    siginfo_t info{};
    const int sig = ::sigtimedwait(&block.set(), &info, &ts);
    if (sig == SIGINT || sig == SIGTERM || sig == SIGHUP) {
      ev.kind = ChildEvent::Signalled;
      ev.signal = sig;
      return ev;
    }
    if (reap(pid, ev.status)) {
      ev.kind = ChildEvent::Exited;
      return ev;
    }
  }
}

int stop_child(pid_t pid, double grace_s) {
  // kill(-pid) signals the child's process group; pid <= 1 would make it every
  // process (-1) or our own group (0).
  if (pid <= 1) throw std::logic_error("stop_child: not a child process id: " + std::to_string(pid));
  int status = 0;
  if (reap(pid, status)) return status;
  ::kill(-pid, SIGTERM);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(grace_s);
  while (std::chrono::steady_clock::now() < deadline) {
    if (reap(pid, status)) return status;
    ::usleep(20000);
  }
  ::kill(-pid, SIGKILL);
  int st = 0;
  while (::waitpid(pid, &st, 0) < 0 && errno == EINTR) {
  }
  return decode_status(st);
}

}  // namespace robozoo
