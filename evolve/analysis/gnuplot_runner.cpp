#include "evolve/analysis/gnuplot_runner.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <stdexcept>
#include <vector>

namespace robozoo {

namespace {

struct Finished {
  int status = -1;  ///< exit status, 128 + signal, or -1 when it could not start
  std::string output;
};

// Runs argv with stdin from /dev/null and stdout+stderr captured.
Finished run_captured(const std::vector<std::string>& argv) {
  Finished f;
  int fds[2];
  if (::pipe(fds) != 0) return f;
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    return f;
  }
  if (pid == 0) {
    ::dup2(fds[1], 1);
    ::dup2(fds[1], 2);
    ::close(fds[0]);
    ::close(fds[1]);
    std::vector<char*> args;
    for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    ::execvp(args[0], args.data());
    ::_exit(127);
  }
  ::close(fds[1]);
  char buf[4096];
  ssize_t n;
  while ((n = ::read(fds[0], buf, sizeof buf)) > 0 || (n < 0 && errno == EINTR))
    if (n > 0) f.output.append(buf, static_cast<size_t>(n));
  ::close(fds[0]);
  int st = 0;
  while (::waitpid(pid, &st, 0) < 0 && errno == EINTR) {
  }
  f.status = WIFEXITED(st) ? WEXITSTATUS(st) : 128 + WTERMSIG(st);
  return f;
}

}  // namespace

bool gnuplot_available(const std::string& gnuplot) {
  const Finished f = run_captured({gnuplot, "-e", "set terminal pngcairo; print 'ok'"});
  return f.status == 0 && f.output.find("ok") != std::string::npos;
}

void run_gnuplot(const std::string& script_path, const std::string& gnuplot) {
  const Finished f = run_captured({gnuplot, script_path});
  if (f.status == 127) throw std::runtime_error("cannot run " + gnuplot + " (install gnuplot-nox)");
  if (f.status != 0)
    throw std::runtime_error(gnuplot + " failed on " + script_path + " (exit status " + std::to_string(f.status) +
                             "): " + f.output);
}

}  // namespace robozoo
