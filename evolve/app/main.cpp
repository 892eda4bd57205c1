// robozoo-evolve: CPPN-NEAT evolution of complete robots, published over LCM
// and logged; `robozoo-evolve eval` grows and simulates one genome;
// `mpirun -np N robozoo-evolve --mpi ...` evaluates on the ranks of an MPI job.
#include <unistd.h>

#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <thread>

#include "evolve/app/champion_command.hpp"
#include "evolve/app/eval_command.hpp"
#include "evolve/app/mpi_command.hpp"
#include "evolve/app/run_command.hpp"
#include "util/stop_signals.hpp"
#include "evolve/parallel/mpi/mpi_session.hpp"
#include "evolve/core/version.hpp"
#include "util/parse_options.hpp"

int main(int argc, char** argv) {
  std::unique_ptr<robozoo::MpiSession> session;
  std::unique_ptr<robozoo::StopWatcher> watcher;  // destroyed before the session
  if (robozoo::mpi_requested(argc, argv)) {
    try {
      robozoo::block_stop_signals();  // before MPI starts its threads: they inherit the mask
      session = std::make_unique<robozoo::MpiSession>(&argc, &argv);
      if (session->rank() == 0)
        watcher = std::make_unique<robozoo::StopWatcher>("robozoo-evolve");
      else  // worker ranks end silently, after rank 0 has had time to say how to resume
        watcher = std::make_unique<robozoo::StopWatcher>("", robozoo::kWorkerStopDelay);
    } catch (const std::exception& e) {
      std::cerr << "robozoo-evolve: --mpi: " << e.what() << "\n";
      return 2;
    }
  }
  const bool silent = session && session->rank() != 0;  // only rank 0 prints help and errors

  CLI::App app{
      "robozoo-evolve: evolve complete robots (body, joints, sensors, CTRNN brain) with CPPN-NEAT,\n"
      "selected for directed displacement in ODE. Every event goes to an LCM log (and, with --lcm-url,\n"
      "to the LCM bus); a checkpoint after every generation lets --resume continue a killed run.\n"
      "On a cluster: mpirun -np N robozoo-evolve --mpi ... (rank 0 evolves, the others evaluate).\n"
      "Precedence of settings: defaults < --preset < --config FILE < command-line flags."};
  app.set_version_flag("--version", robozoo::version_line());
  robozoo::RunOptions run;
  robozoo::add_run_options(app, run);
  robozoo::EvalOptions eval;
  CLI::App* eval_cmd =
      app.add_subcommand("eval",
                         "Grow and simulate one genome (random from a seed, or from a genome JSON file), print "
                         "its morphology, outcome and fitness");
  robozoo::add_eval_options(*eval_cmd, eval);
  robozoo::ChampionOptions champion;
  CLI::App* champion_cmd =
      app.add_subcommand("champion",
                         "Write the best-of-run champion of a compact result (robozoo-experiment's results/) as a "
                         "one-generation log for robozoo-render video, robozoo-replay check and robozoo-view, after "
                         "checking that this build evaluates it to the committed fitness");
  robozoo::add_champion_options(*champion_cmd, champion);
  if (const auto stop = robozoo::parse_options(app, argc, argv, "robozoo-evolve", silent)) return *stop;
  if (eval_cmd->parsed()) {
    if (session) {
      if (!silent) std::cerr << "robozoo-evolve: --mpi is for evolution runs, not for eval\n";
      return 2;
    }
    return robozoo::run_eval_command(eval);
  }
  if (champion_cmd->parsed()) {
    if (session) {
      if (!silent) std::cerr << "robozoo-evolve: --mpi is for evolution runs, not for champion\n";
      return 2;
    }
    return robozoo::run_champion_command(champion);
  }
  if (session)
    return session->rank() == 0 ? robozoo::run_mpi_root(app, run, *session, *watcher)
                                : robozoo::run_mpi_worker(*session);
  return robozoo::run_run_command(app, run);
}
