#pragma once
// What the worker pool needs from whatever carries jobs to workers: N worker
// slots, each running the worker side of the protocol (worker.hpp) somewhere.
// PipeTransport (forked children over socket pairs) is the local implementation;
// an MPI transport would map slots to ranks 1..N and frames to messages.
//
// The pool drives a transport from one thread, one worker at a time: it sends a
// job only to a worker that has no job outstanding, so a transport never queues
// more than one job per worker.
#include <optional>
#include <string>

#include "evolve/parallel/protocol.hpp"

namespace robozoo {

/// Something a worker did, as seen by the pool.
struct WorkerEvent {
  enum class Kind {
    Result,  ///< the worker answered a job (result.ok false: the work function threw)
    Died,    ///< the worker is gone (crash, exit, broken protocol); restart() it
  };
  Kind kind = Kind::Result;
  int worker = -1;     ///< slot, 0 .. size()-1
  Result result;       ///< Kind::Result
  std::string reason;  ///< Kind::Died: why, e.g. "killed by signal 9 (Killed)"
};

class Transport {
 public:
  virtual ~Transport() = default;

  /// Number of worker slots.
  virtual int size() const = 0;

  /// Hands a job to worker w (which has no job outstanding). Returns false, and
  /// delivers nothing, when w is already known to be dead: its Died event is then
  /// pending in receive(). A worker that dies during or after the send is reported
  /// by receive() as Died. Never blocks on a worker that does not read: a transport
  /// buffers what it cannot send at once and sends it on from receive().
  virtual bool send(int w, const Job& job) = 0;

  /// The next event from any worker, waiting at most timeout_s seconds (0: only
  /// what is available now); empty on timeout. Every death is reported exactly
  /// once, after any result that worker completed before dying.
  virtual std::optional<WorkerEvent> receive(double timeout_s) = 0;

  /// Replaces worker w with a fresh one: kills it if it still runs (e.g. it hangs),
  /// reaps it, releases its resources and drops anything it sent that receive() has
  /// not returned yet. Afterwards w is idle. Throws std::runtime_error if no worker
  /// can be started (a transport that cannot replace workers, e.g. plain MPI,
  /// throws here and the pool fails the run with that message).
  virtual void restart(int w) = 0;
};

}  // namespace robozoo
