#pragma once
// The MPI transport: rank 0 of MPI_COMM_WORLD owns the WorkerPool, and worker slot
// w is rank w + 1, which runs serve_mpi_session (mpi_worker.hpp) on the same worker
// code as a local pipe worker (serve_frame). One frame travels as one message:
// Job and Shutdown frames from rank 0 with tag 1 + 2s, Result and Failure frames
// back with tag 2 + 2s in session s (the protocol of evolve/parallel/protocol.hpp,
// unchanged).
//
// Lifecycle: construct (no communication), start(setup) broadcasts the session's
// setup text to every worker rank, then the pool sends jobs. The worker ranks may
// serve several sessions in a row (one MpiTransport after the other on rank 0):
// give each its own `session` number, so that a result still on its way from an
// abandoned session never reaches the next one. The destructor sends
// every worker rank a Shutdown frame (or, if start() never ran, tells them that no
// session follows), so the worker ranks' loop ends and all ranks can finalise.
//
// Receiving polls MPI_Improbe with short sleeps (growing from poll_min_sleep_s to
// poll_max_sleep_s while nothing arrives), so that an idle rank 0 leaves its core
// to the workers instead of spinning inside MPI.
//
// Plain MPI cannot start a rank into a running job: restart() throws (the pool then
// fails the map with that message). A rank that sends a frame that does not check
// out, or whose messages MPI reports as failed, is reported Died. A rank that is
// killed usually ends the whole job first (Open MPI's default): robozoo-evolve's
// rank 0 then leaves with a message saying how to resume from its checkpoint.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "evolve/parallel/protocol.hpp"
#include "evolve/parallel/transport.hpp"

namespace robozoo {

struct MpiTransportParams {
  uint32_t session = 0;                            ///< this session's number (its tags); differ from the previous one
  double poll_min_sleep_s = 20e-6;                 ///< first pause after a probe that found nothing (s)
  double poll_max_sleep_s = 1e-3;                  ///< longest pause: the most latency polling adds to a result (s)
  double shutdown_wait_s = 10.0;                   ///< the destructor waits this long for its Shutdown sends (s)
  uint32_t max_body_bytes = kDefaultMaxBodyBytes;  ///< largest frame body accepted (bytes)
  bool record_jobs = false;                        ///< keep every job's timing in stats().timings (benchmarks)
};

/// One job as rank 0 saw it (record_jobs).
struct MpiJobTiming {
  int worker = -1;         ///< slot (rank - 1)
  uint64_t index = 0;      ///< the job's index in its map()
  uint64_t bytes_out = 0;  ///< size of the Job message (bytes)
  uint64_t bytes_in = 0;   ///< size of the Result message (bytes)
  double seconds = 0.0;    ///< from handing the job to MPI to receiving its result (s)
};

struct MpiTransportStats {
  uint64_t messages_sent = 0;         ///< Job and Shutdown messages (count)
  uint64_t messages_received = 0;     ///< Result and Failure messages (count)
  uint64_t bytes_sent = 0;            ///< bytes of the messages sent (bytes)
  uint64_t bytes_received = 0;        ///< bytes of the messages received (bytes)
  uint64_t setup_bytes = 0;           ///< bytes of the setup broadcast (bytes)
  std::vector<uint64_t> jobs;         ///< results received, per worker (count)
  std::vector<double> busy_seconds;   ///< time with a job outstanding, per worker (s)
  std::vector<MpiJobTiming> timings;  ///< every job, when record_jobs
};

class MpiTransport : public Transport {
 public:
  /// On rank 0 of an initialised MPI job of at least 2 ranks (MpiSession). Throws
  /// std::invalid_argument elsewhere (another rank, or a single rank), naming why.
  explicit MpiTransport(MpiTransportParams params = {});
  /// Sends Shutdown to every worker rank (or "no session" if never started).
  ~MpiTransport() override;
  MpiTransport(const MpiTransport&) = delete;
  MpiTransport& operator=(const MpiTransport&) = delete;

  /// Starts the session: every worker rank receives `setup` (receive_setup) and
  /// builds its work function from it. Once only; before any send().
  void start(const std::string& setup);
  bool started() const;

  int size() const override;
  bool send(int w, const Job& job) override;
  std::optional<WorkerEvent> receive(double timeout_s) override;
  /// Always throws std::runtime_error: MPI cannot replace a rank of a running job.
  /// The message names the rank and what became of it.
  void restart(int w) override;

  /// MPI rank of worker slot w.
  static int rank_of(int w) { return w + 1; }
  const MpiTransportStats& stats() const;
  void reset_stats();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace robozoo
