#pragma once
// Test support: run robozoo's programs as a user would, from the build tree.
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace robozoo::testing {

inline std::string bin(const std::string& name) { return std::string(ROBOZOO_BIN_DIR) + "/" + name; }

struct Outcome {
  int status = -1;     ///< exit status, or 128 + signal
  std::string output;  ///< stdout and stderr together
};

/// Runs a shell command line, waits, returns its exit status and output.
inline Outcome run_shell(const std::string& command) {
  Outcome o;
  FILE* p = ::popen((command + " 2>&1").c_str(), "r");
  if (!p) return o;
  char buf[4096];
  size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, p)) > 0) o.output.append(buf, n);
  const int st = ::pclose(p);
  o.status = WIFEXITED(st) ? WEXITSTATUS(st) : 128 + WTERMSIG(st);
  return o;
}

/// Starts argv in the background (stdout/stderr to `log_file`); returns its pid.
inline pid_t spawn(const std::vector<std::string>& argv, const std::string& log_file) {
  const pid_t pid = ::fork();
  if (pid < 0) {
    ADD_FAILURE() << "fork failed";
    return -1;
  }
  if (pid == 0) {
    const int fd = ::open(log_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) {
      ::dup2(fd, 1);
      ::dup2(fd, 2);
    }
    std::vector<char*> args;
    for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    ::execv(args[0], args.data());
    ::_exit(127);
  }
  return pid;
}

/// kill(2) for one real process only. kill(-1, sig) signals every process the
/// user may signal (as root: the whole machine, the test runner included), and
/// kill(0, sig) the caller's own group: a lookup that found no process must never
/// turn into either.
inline bool kill_process(pid_t pid, int sig) {
  if (pid <= 1) {
    ADD_FAILURE() << "refusing to signal pid " << pid << " (no such process was found)";
    return false;
  }
  return ::kill(pid, sig) == 0;
}

inline int wait_status(pid_t pid) {
  int st = 0;
  ::waitpid(pid, &st, 0);
  return WIFEXITED(st) ? WEXITSTATUS(st) : 128 + WTERMSIG(st);
}

inline bool file_exists(const std::string& p) {
  struct stat st {};
  return ::stat(p.c_str(), &st) == 0;
}

inline std::string read_file(const std::string& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

/// A fresh temporary folder, removed with its contents at destruction.
struct TempDir {
  std::string path;
  TempDir() {
    char tmpl[] = "/tmp/robozoo_test_XXXXXX";
    path = ::mkdtemp(tmpl);
  }
  ~TempDir() { std::system(("rm -rf '" + path + "'").c_str()); }
  std::string operator/(const std::string& name) const { return path + "/" + name; }
};

/// Waits up to `seconds` for no process's command line to match `pattern`
/// (pgrep -f); returns pgrep's output for those still left ("" when none is).
/// Write one character of the pattern as a class ("[r]ecurrent") so that the
/// pattern does not match the shell that runs pgrep.
inline std::string processes_left(const std::string& pattern, double seconds = 2.0) {
  std::string left;
  for (int i = 0; i <= static_cast<int>(seconds * 100); ++i) {
    left = run_shell("pgrep -f '" + pattern + "'").output;
    if (left.empty()) break;
    ::usleep(10000);
  }
  return left;
}

/// Child process ids of `pid` (from /proc).
inline std::vector<pid_t> children_of(pid_t pid) {
  std::vector<pid_t> out;
  std::ifstream in("/proc/" + std::to_string(pid) + "/task/" + std::to_string(pid) + "/children");
  pid_t c;
  while (in >> c) out.push_back(c);
  return out;
}

}  // namespace robozoo::testing
