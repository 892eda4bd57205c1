#pragma once
// The local transport: each worker is a fork()ed child process of the pool's
// process, talking to it over one AF_UNIX stream socket pair. Processes, not
// threads, because ODE's random seed is process-global (docs/method.md section 4).
//
// The child runs the work function it inherited in a loop (read a Job frame,
// reply with a Result/Failure frame) until its socket reaches end-of-file, it gets
// a Shutdown frame, or its parent dies (PR_SET_PDEATHSIG). It closes every
// inherited descriptor other than its own socket and stdin/stdout/stderr (so
// it holds no other worker's socket and no file of the parent), ignores SIGINT
// (Ctrl-C reaches the parent, which decides), and leaves with _exit() so no
// parent's atexit handler or buffered output runs twice.
//
// The parent never gets SIGPIPE (it writes with MSG_NOSIGNAL), never blocks on a
// worker (non-blocking sockets, poll() with timeouts), reaps every child it
// starts (no zombies) and closes every socket it opens (no descriptor leaks).
//
// fork() copies only the calling thread: create the pool before starting other
// threads (or make sure the work function takes no lock another thread may hold),
// as restarts fork again later from the same process. Linux delivers the
// parent-death signal when the forking *thread* ends: create and use the pool
// from a thread that outlives it (the main thread).
#include <sys/types.h>

#include <deque>
#include <string>
#include <vector>

#include "evolve/parallel/protocol.hpp"
#include "evolve/parallel/transport.hpp"
#include "evolve/parallel/worker.hpp"

namespace robozoo {

struct PipeTransportParams {
  double shutdown_grace_s = 2.0;                   ///< the destructor waits this long for workers to exit
                                                   ///< after closing their sockets, then SIGKILLs them (s)
  bool close_inherited_fds = true;                 ///< children close all descriptors >= 3 but their socket
  uint32_t max_body_bytes = kDefaultMaxBodyBytes;  ///< largest frame body accepted (bytes)
};

class PipeTransport : public Transport {
 public:
  /// Starts `workers` (>= 1) children running fn. Throws std::invalid_argument on
  /// bad arguments, std::system_error if a child cannot be started.
  PipeTransport(int workers, WorkFn fn, PipeTransportParams params = {});
  ~PipeTransport() override;
  PipeTransport(const PipeTransport&) = delete;
  PipeTransport& operator=(const PipeTransport&) = delete;

  int size() const override { return static_cast<int>(slots_.size()); }
  bool send(int w, const Job& job) override;
  std::optional<WorkerEvent> receive(double timeout_s) override;
  void restart(int w) override;

  /// Process id of worker w (-1 while it is dead and not yet restarted).
  pid_t pid(int w) const;

 private:
  struct Slot {
    pid_t pid = -1;
    int fd = -1;          ///< parent's end of the socket pair, non-blocking
    Bytes out;            ///< encoded bytes not yet written
    size_t out_sent = 0;  ///< bytes of `out` already written
    FrameReader reader;
  };

  void spawn(int w);
  /// Marks w dead: closes its socket, reaps it (killing it first if kill_now, or if
  /// it still runs after a short wait) and queues its Died event with `why` and its
  /// exit status.
  void bury(int w, const std::string& why, bool kill_now);
  /// Kills (if running) and reaps w's process and closes its socket, no event.
  void discard(int w);
  void flush_out(int w);  ///< writes what it can of w's pending bytes
  void read_from(int w);  ///< reads what is available from w, queueing events
  void check(int w) const;

  WorkFn fn_;
  PipeTransportParams params_;
  std::vector<Slot> slots_;
  std::deque<WorkerEvent> events_;  ///< ready to be returned by receive(), oldest first
};

}  // namespace robozoo
