#pragma once
// The worker side under MPI: what every rank but 0 runs. It waits for rank 0's
// setup (MpiTransport::start), builds its work function from it, and serves Job
// frames from rank 0 with the local pool's worker code (serve_frame) until a
// Shutdown frame: the transport changes, the protocol does not.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "evolve/parallel/protocol.hpp"
#include "evolve/parallel/worker.hpp"

namespace robozoo {

struct MpiWorkerParams {
  double poll_min_sleep_s = 20e-6;                 ///< first pause after a probe that found no job (s)
  double poll_max_sleep_s = 1e-3;                  ///< longest pause: the most latency polling adds to a job (s)
  uint32_t max_body_bytes = kDefaultMaxBodyBytes;  ///< largest frame body accepted (bytes)
};

struct MpiWorkerStats {
  uint64_t jobs = 0;          ///< jobs served, over all sessions (count)
  double busy_seconds = 0.0;  ///< time spent in the work function (s)
};

/// Builds a session's work function from rank 0's setup text; may throw for a
/// setup it cannot use.
using WorkFnFactory = std::function<WorkFn(const std::string& setup)>;

/// One session on a worker rank (not rank 0): waits for rank 0's setup, builds the
/// work function and serves jobs until rank 0 sends Shutdown; returns true. Returns
/// false at once when rank 0 announces that no session follows. A rank may serve
/// several sessions in a row (one per MpiTransport on rank 0). Throws ProtocolError
/// for a frame from rank 0 that does not check out, std::runtime_error on an MPI
/// error, and whatever `make` throws: the caller then ends the job (MPI_Abort),
/// as rank 0 would wait for this rank forever.
bool serve_mpi_session(const WorkFnFactory& make, MpiWorkerStats* stats = nullptr, MpiWorkerParams params = {});

/// Collective, every rank: each gives its statistics (rank 0 its own, usually
/// empty); rank 0 gets them all, indexed by rank, the other ranks an empty vector.
/// Throws std::runtime_error on an MPI error.
std::vector<MpiWorkerStats> gather_worker_stats(const MpiWorkerStats& mine);

}  // namespace robozoo
