#pragma once
// Test helpers for the process pool: descriptor counts, child-process checks and a
// scratch directory for marker files (a worker's memory is lost when it dies, so
// "first attempt" is remembered on disk).
#include <dirent.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace robozoo::test {

/// Open descriptors of this process (not counting the one used to list them).
inline int open_fd_count() {
  DIR* d = ::opendir("/proc/self/fd");
  if (!d) throw std::runtime_error("cannot list /proc/self/fd");
  int n = 0;
  while (const dirent* e = ::readdir(d))
    if (e->d_name[0] != '.') ++n;
  ::closedir(d);
  return n - 1;
}

/// Targets of this process's open descriptors, e.g. "socket:[1234]", "/dev/null".
inline std::vector<std::string> open_fd_targets() {
  std::vector<std::string> out;
  DIR* d = ::opendir("/proc/self/fd");
  if (!d) throw std::runtime_error("cannot list /proc/self/fd");
  const int own = ::dirfd(d);
  while (const dirent* e = ::readdir(d)) {
    if (e->d_name[0] == '.' || std::atoi(e->d_name) == own) continue;
    std::error_code ec;
    const auto target = std::filesystem::read_symlink(std::string("/proc/self/fd/") + e->d_name, ec);
    out.push_back(std::string(e->d_name) + " -> " + (ec ? std::string("?") : target.string()));
  }
  ::closedir(d);
  return out;
}

/// True if some child of this process has ended and not been reaped.
inline bool has_zombie_child() {
  siginfo_t info{};
  const int r = ::waitid(P_ALL, 0, &info, WEXITED | WNOHANG | WNOWAIT);
  return r == 0 && info.si_pid != 0;
}

/// True if this process has any child at all (running or not reaped).
inline bool has_any_child() {
  siginfo_t info{};
  const int r = ::waitid(P_ALL, 0, &info, WEXITED | WNOHANG | WNOWAIT);
  return !(r == -1 && errno == ECHILD);
}

/// A fresh directory, removed with its contents at the end of the scope.
class TempDir {
 public:
  TempDir() {
    const char* base = std::getenv("TMPDIR");
    std::string tmpl = std::string(base && *base ? base : "/tmp") + "/robozoo-pool-XXXXXX";
    if (!::mkdtemp(tmpl.data())) throw std::runtime_error("mkdtemp failed");
    path_ = tmpl;
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::string& path() const { return path_; }

  /// Creates `name` and returns true the first time it is called for that name
  /// (in any process); false afterwards.
  static bool first_time(const std::string& dir, const std::string& name) {
    const std::string p = dir + "/" + name;
    std::error_code ec;
    if (std::filesystem::exists(p, ec)) return false;
    std::ofstream(p) << "seen\n";
    return true;
  }

 private:
  std::string path_;
};

}  // namespace robozoo::test
