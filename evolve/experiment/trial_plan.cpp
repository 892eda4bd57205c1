#include "evolve/experiment/trial_plan.hpp"

#include <stdexcept>

#include "evolve/config/run_config.hpp"

namespace robozoo {

std::string Trial::name() const { return regime_name(regime) + "-s" + std::to_string(seed); }

void validate_experiment(const ExperimentParams& p) {
  auto need = [](bool ok, const std::string& what) {
    if (!ok) throw std::invalid_argument(what);
  };
  need(p.trials >= 1, "--trials must be >= 1, got " + std::to_string(p.trials));
  need(p.generations >= 1, "--generations must be >= 1, got " + std::to_string(p.generations));
  need(p.population >= 2, "--population must be >= 2, got " + std::to_string(p.population));
  need(p.steps >= 0, "--steps must be >= 1, got " + std::to_string(p.steps));
  need(p.workers >= 0, "--workers must be >= 1, got " + std::to_string(p.workers));
  need(p.mpi_ranks == 0 || p.mpi_ranks >= 2,
       "--mpi needs at least 2 ranks (rank 0 evolves, ranks 1.. evaluate), got " + std::to_string(p.mpi_ranks));
  need(p.mpi_ranks == 0 || p.workers == 0,
       "--workers and --mpi exclude each other: with --mpi the trial's ranks 1.. are its workers");
  need(p.mpi_ranks == 0 || (!p.mpirun.empty() && !p.mpirun.front().empty()),
       "--mpirun: the MPI launcher is empty");
  need(!p.out_dir.empty(), "--out: the experiment needs a folder");
}

std::vector<Trial> plan_trials(const ExperimentParams& p) {
  validate_experiment(p);
  std::vector<Trial> out;
  for (int s = 1; s <= p.trials; ++s)
    for (Regime r : {Regime::FeedForward, Regime::Recurrent}) {
      Trial t;
      t.regime = r;
      t.seed = s;
      t.log_path = p.out_dir + "/" + t.name() + ".lcmlog";
      t.output_path = p.out_dir + "/" + t.name() + ".out";
      out.push_back(t);
    }
  return out;
}

std::vector<std::string> evolve_arguments(const Trial& t, const ExperimentParams& p, bool resume) {
  // The sizes go on the command line on resume too: robozoo-evolve takes the run's
  // configuration from the checkpoint, but builds its evaluator from the command
  // line, so a resume without them would evaluate with the default steps.
  std::vector<std::string> a = {"--log", t.log_path, "--quiet", "--regime", regime_name(t.regime), "--seed",
                                std::to_string(t.seed), "--population", std::to_string(p.population),
                                "--generations", std::to_string(p.generations)};
  if (p.steps > 0) a.insert(a.end(), {"--steps", std::to_string(p.steps)});
  if (p.workers > 0) a.insert(a.end(), {"--workers", std::to_string(p.workers)});
  if (resume) a.push_back("--resume");
  return a;
}

std::vector<std::string> trial_command(const Trial& t, const ExperimentParams& p, const std::string& evolve,
                                       bool resume) {
  std::vector<std::string> cmd;
  if (p.mpi_ranks > 0) {
    cmd = p.mpirun;
    cmd.insert(cmd.end(), {"-np", std::to_string(p.mpi_ranks)});
  }
  cmd.push_back(evolve);
  for (auto& a : evolve_arguments(t, p, resume)) cmd.push_back(std::move(a));
  if (p.mpi_ranks > 0) cmd.push_back("--mpi");
  return cmd;
}

}  // namespace robozoo
