#pragma once
// Running robozoo-evolve as a child of robozoo-experiment so that Ctrl-C stops
// the whole experiment cleanly.
//
// While a SignalBlock lives, SIGINT, SIGTERM, SIGHUP and SIGCHLD are blocked in
// the calling (single-threaded) process and taken with sigtimedwait: no signal
// handler, no global flag. A child runs in its own process group, so a Ctrl-C
// at the terminal reaches the driver only; the driver then sends SIGTERM to the
// child's group (robozoo-evolve and its workers). robozoo-evolve checkpoints
// atomically after every generation, so a child stopped at any moment is
// resumed later from its last finished generation. A child also receives
// SIGTERM if the driver dies (PR_SET_PDEATHSIG).
#include <sys/types.h>

#include <csignal>
#include <string>
#include <vector>

namespace robozoo {

class SignalBlock {
 public:
  SignalBlock();
  ~SignalBlock();
  SignalBlock(const SignalBlock&) = delete;
  SignalBlock& operator=(const SignalBlock&) = delete;
  const sigset_t& set() const { return set_; }

 private:
  sigset_t set_{};
  sigset_t old_{};
};

/// Starts `argv` (argv[0] a path) in a new process group with the signals
/// unblocked, stdin from /dev/null and stdout and stderr appended to
/// `output_path`. Throws std::runtime_error when it cannot start.
pid_t spawn_child(const std::vector<std::string>& argv, const std::string& output_path);

struct ChildEvent {
  enum Kind { Exited, Signalled, Timeout } kind = Timeout;
  int status = 0;  ///< Exited: exit status (128 + signal when the child was killed)
  int signal = 0;  ///< Signalled: the signal the driver received (SIGINT, SIGTERM, SIGHUP)
};

/// Waits up to `timeout_s` for the child to end or for a stop signal to the driver.
ChildEvent wait_child(const SignalBlock& block, pid_t pid, double timeout_s);

/// Sends SIGTERM to the child's process group and waits for the child;
/// SIGKILL after `grace_s` seconds. Returns its exit status (128 + signal).
int stop_child(pid_t pid, double grace_s = 10.0);

}  // namespace robozoo
