#include "evolve/app/mpi_command.hpp"

#include <algorithm>
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "evolve/parallel/mpi/mpi_transport.hpp"
#include "evolve/parallel/mpi/mpi_worker.hpp"
#include "evolve/run/pool_evaluator.hpp"

namespace robozoo {

namespace {
/// What is on disk and how to go on.
std::string intact(const Evolution& evo, const EvolveOptions& opts) {
  return "the checkpoint " + evo.checkpoint_path() + " is intact after " +
         std::to_string(std::max(0, evo.checkpointed_generations())) + " of " +
         std::to_string(evo.config().generations) + " generations; " + resume_hint(opts.log_path);
}
}  // namespace

std::string resume_hint(const std::string& log_path) {
  return "the run can be resumed with: robozoo-evolve --log " + log_path +
         " --resume (with --mpi under mpirun, any number of ranks >= 2, or on one machine with --workers N)";
}

int run_mpi_root(const CLI::App& app, const RunOptions& o, const MpiSession& session, StopWatcher& watcher) {
  if (session.size() < 2) {
    std::cerr << "robozoo-evolve: --mpi needs at least 2 ranks (rank 0 evolves, ranks 1.. evaluate), this job has "
              << session.size() << ": start it with mpirun -np N (N >= 2), or leave out --mpi and use --workers\n";
    return 2;
  }
  try {
    // The evaluator exists before anything can fail: its transport releases the
    // worker ranks whichever way rank 0 leaves (no session, or Shutdown).
    auto owned = std::make_unique<MpiTransport>();
    MpiTransport& transport = *owned;
    PoolEvaluator evaluator(std::move(owned), o.job_timeout);
    const std::string ranks = std::to_string(transport.size()) + " worker ranks";

    RunConfig config;
    EvolveOptions opts;
    if (const auto status = resolve_run(app, o, config, opts)) return *status;
    // Rank 0's largest serial cost, overlapped with the next generation's evaluations.
    opts.background_checkpoint = true;
    // And the next largest: a new champion's re-simulation for its pose stream.
    opts.overlap_trajectory = true;
    std::unique_ptr<Evolution> evo;
    if (const auto status = open_evolution(config, opts, evaluator, evo)) return *status;
    // Said when mpirun stops rank 0, made then (the checkpoint may be on its way);
    // forgotten before `evo` goes, whichever way this scope ends.
    watcher.set_message_source([&evo = *evo, &opts] {
      return "an MPI rank died or the job was cancelled (mpirun's message names the rank); " + intact(evo, opts);
    });
    struct Forget {
      StopWatcher& w;
      ~Forget() { w.set_message(""); }
    } forget{watcher};
    try {
      // The worker ranks evaluate with the run's configuration, as resolved here
      // (from the checkpoint when resuming).
      transport.start(config_to_json(evo->config()).dump());
      if (!o.quiet) std::cerr << run_banner(*evo, opts, ranks);
      evo->run([&](const ProgressReport& r) {
        if (!o.quiet) std::cerr << format_progress(r) << std::endl;
      });
    } catch (const std::exception& e) {
      std::string also;
      try {
        evo->wait_for_checkpoint();
      } catch (const std::exception& w) {
        also = " (and the last checkpoint could not be written: " + std::string(w.what()) + ")";
      }
      std::cerr << "robozoo-evolve: " << e.what() << also << "; " << intact(*evo, opts) << std::endl;
      session.abort(1);  // a rank may be hung in a job: end every rank now
    }
    print_run_end(*evo, opts, o.quiet);
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "robozoo-evolve: " << e.what() << "\n";
    session.abort(1);
  }
}

int run_mpi_worker(const MpiSession& session) {
  try {
    serve_mpi_session([](const std::string& setup) { return WorkFn(eval_work_from_setup(setup)); });
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "robozoo-evolve: rank " << session.rank() << " on " << session.host() << ": " << e.what() << "\n";
    session.abort(1);
  }
}

}  // namespace robozoo
