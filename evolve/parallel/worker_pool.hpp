#pragma once
// The parallel evaluation engine: a pool of worker processes that evaluates a
// batch of jobs and returns the results in job order, so a run is bit-identical
// for any number of workers (each job is a pure function of its payload).
//
// Jobs are handed out dynamically (a free worker takes the next job: robots differ
// widely in cost). A worker that crashes (a signal, an exit, a broken frame) or
// hangs past job_timeout_s is replaced and its job evaluated again; a job whose
// worker dies max_attempts times fails the map() with a PoolError naming it, and
// so does a job whose work function throws (a pure function would throw again).
//
// Even one worker is a child process, never the calling process: the work runs
// under the same isolation for every worker count (its crash cannot take the run
// down, ODE's process-global state is its own), so results cannot depend on the
// count. Not thread-safe: one thread owns a pool.
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "evolve/parallel/pipe_transport.hpp"
#include "evolve/parallel/protocol.hpp"
#include "evolve/parallel/transport.hpp"
#include "evolve/parallel/worker.hpp"

namespace robozoo {

struct PoolParams {
  double job_timeout_s = 600.0;  ///< a job running longer gets its worker killed and replaced,
                                 ///< and is handed out again; +infinity: no limit (s)
  int max_attempts = 3;          ///< a job whose worker dies (crash or timeout) this many times
                                 ///< fails the map (count, >= 1)
  PipeTransportParams pipe;      ///< the local transport's settings (unused with a given transport)
};

struct PoolStats {
  uint64_t maps = 0;            ///< map() calls that returned results (count)
  uint64_t jobs_completed = 0;  ///< results received (count)
  uint64_t worker_deaths = 0;   ///< workers found dead: crashed, exited, broke the protocol (count)
  uint64_t job_timeouts = 0;    ///< jobs that ran past job_timeout_s (count)
  uint64_t restarts = 0;        ///< workers replaced, for any reason (count)
  uint64_t jobs_reissued = 0;   ///< jobs handed out again after their worker died or hung (count)
};

/// A map() that cannot complete: a job failed (its error names the job).
class PoolError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class WorkerPool {
 public:
  /// `workers` (>= 1) child processes running fn (PipeTransport). Throws
  /// std::invalid_argument on bad arguments, std::system_error if a child cannot start.
  WorkerPool(int workers, WorkFn fn, PoolParams params = {});
  /// A pool over any transport (e.g. a later MPI transport whose ranks run the
  /// work function themselves).
  explicit WorkerPool(std::unique_ptr<Transport> transport, PoolParams params = {});
  /// Closes the transport: workers finish and exit, stragglers are killed.
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  /// Evaluates every job; result i belongs to jobs[i]. Throws PoolError when a job
  /// fails (its work function threw, or its worker died max_attempts times); the
  /// pool stays usable afterwards (workers busy with abandoned jobs are replaced).
  std::vector<Bytes> map(const std::vector<Bytes>& jobs);

  int workers() const { return transport_->size(); }
  const PoolStats& stats() const { return stats_; }
  const PoolParams& params() const { return params_; }
  Transport& transport() { return *transport_; }

 private:
  enum class State { Idle, Busy, Down };  ///< Down: dead, its Died event not yet received
  struct Slot {
    State state = State::Idle;
    size_t job = 0;       ///< the job it runs when Busy
    double deadline = 0;  ///< when that job times out (s on the pool's clock)
  };
  struct MapRun;  // the bookkeeping of one map() call

  void validate() const;
  double now() const;
  void restart(int w);
  void assign(MapRun& run);
  void handle(MapRun& run, WorkerEvent event);
  void expire(MapRun& run);
  /// Charges a failed attempt (crash, timeout) to job j: reissue it, or fail.
  void charge(MapRun& run, size_t j, const std::string& reason);
  /// Replaces every worker still busy with a job of an abandoned map().
  void abandon() noexcept;

  std::unique_ptr<Transport> transport_;
  PoolParams params_;
  std::vector<Slot> slots_;
  PoolStats stats_;
  bool broken_ = false;  ///< a worker could not be replaced: no further map()
  std::string broken_reason_;
};

}  // namespace robozoo
