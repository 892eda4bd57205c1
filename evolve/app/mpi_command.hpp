#pragma once
// robozoo-evolve --mpi: the run on the ranks of an MPI job. Rank 0 runs everything
// a local run does (NEAT, log, live publishing, checkpoints) with its WorkerPool
// over an MpiTransport; ranks 1..N-1 evaluate, with the local workers' code.
#include <CLI/CLI.hpp>

#include <chrono>
#include <string>

#include "evolve/app/run_command.hpp"
#include "util/stop_signals.hpp"
#include "evolve/parallel/mpi/mpi_session.hpp"

namespace robozoo {

/// Rank 0. Returns the exit status as run_run_command does (2: bad configuration,
/// files, or a job of one rank). A failure during the run prints one line (what
/// failed and how to resume) and ends the whole job (MPI_Abort). `watcher` turns
/// mpirun's SIGTERM (a rank died, the job was cancelled) into a line saying how to resume.
int run_mpi_root(const CLI::App& app, const RunOptions& o, const MpiSession& session, StopWatcher& watcher);

/// How long a worker rank lives on after a stop signal (SIGTERM from mpirun, a
/// cancelled job): rank 0 is stopped by the same signal and says how to resume
/// first; mpirun's SIGKILL after rank 0's exit (or its own timeout, 1 s by
/// default) ends the workers. Longer than that timeout, shorter than a batch
/// system's grace before its own SIGKILL (Slurm's KillWait: 30 s by default).
constexpr std::chrono::milliseconds kWorkerStopDelay{5000};

/// Ranks 1..N-1: evaluate what rank 0 sends until it is done; 0 then. A failure
/// (a bad frame, an MPI error) prints one line naming the rank and ends the job.
int run_mpi_worker(const MpiSession& session);

/// "the run can be resumed with: robozoo-evolve --log LOG --resume ..." (one line's end).
std::string resume_hint(const std::string& log_path);

}  // namespace robozoo
