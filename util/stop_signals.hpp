#pragma once
// Ending a process cleanly when it is told to stop (SIGTERM, SIGINT, SIGHUP): under
// mpirun, rank 0 gets SIGTERM when another rank dies or the job is cancelled, and
// must leave at once with a line that says how to resume. A thread of its own waits
// for those signals (sigwait), so nothing runs in a signal handler: the signals are
// blocked in every other thread (block them before any thread starts, MPI's
// included). On a signal it writes "<program>: stopped by signal N (name): <message>"
// to stderr and ends the process (_exit(128 + N)) without writing anything else:
// files written atomically (the checkpoint) are whole, the log is cut back to the
// checkpoint on --resume.
//
// A worker rank watches too, silently and with a delay: Open MPI's mpirun stops a
// job with SIGCONT, a pause, SIGTERM to every rank, a pause, SIGKILL; but the
// second pause is glibc's sleep(), which an arriving SIGCHLD cuts short to zero
// whole seconds left. A worker that died of the SIGTERM at once would wake mpirun
// into its SIGKILL before a busy rank 0 had written its line (measured: rank 0
// niced to 19 beside 6 busy loops said nothing in 15 of 20 cancelled jobs). So the
// workers outlive rank 0: the SIGKILL that follows rank 0's exit ends them.
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

namespace robozoo {

/// Blocks SIGTERM, SIGINT and SIGHUP in the calling thread, and so in every thread
/// it starts afterwards. Throws std::system_error on failure.
void block_stop_signals();
/// Unblocks them in the calling thread (their default action applies again).
void unblock_stop_signals();
/// Blocks SIGINT and SIGTERM in the calling thread (and so in every thread it
/// starts afterwards) and returns a poll that says, without waiting, whether one
/// of them has arrived since (taking it): for a loop that ends cleanly on Ctrl-C
/// with no handler and no global flag. Throws std::system_error on failure.
std::function<bool()> poll_interrupts();

class StopWatcher {
 public:
  /// Starts the waiting thread; call block_stop_signals() first (std::logic_error if not).
  explicit StopWatcher(std::string program);
  /// The same, waiting `delay` after the signal before it writes and ends the
  /// process; an empty `program` ends it without a line.
  StopWatcher(std::string program, std::chrono::milliseconds delay);
  /// Stops the thread and unblocks the signals in the calling thread: a signal
  /// that arrives afterwards has its default action.
  ~StopWatcher();
  StopWatcher(const StopWatcher&) = delete;
  StopWatcher& operator=(const StopWatcher&) = delete;

  /// What to say after "stopped by signal N (name): " (thread-safe).
  void set_message(const std::string& message);
  /// The same, made when the signal comes (on the watcher's thread, so `source`
  /// must be thread-safe and valid until replaced); empty: say nothing more.
  void set_message_source(std::function<std::string()> source);

 private:
  void watch();
  std::string program_;
  std::chrono::milliseconds delay_{0};
  std::mutex mutex_;
  std::condition_variable stopped_;  ///< ends the delay when the watcher is destroyed
  std::function<std::string()> source_;
  std::atomic<bool> stopping_{false};
  std::thread thread_;
};

}  // namespace robozoo
