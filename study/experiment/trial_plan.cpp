#include "study/experiment/trial_plan.hpp"

#include <stdexcept>

#include "evolve/config/run_config.hpp"

namespace robozoo {

int64_t trial_seed(Arm a, int trial) { return static_cast<int64_t>(kNumArms) * (trial - 1) + static_cast<int>(a) + 1; }

std::string Trial::name() const { return arm_name(arm) + "-s" + std::to_string(seed); }

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
  need(p.mpi_ranks == 0 || (!p.mpirun.empty() && !p.mpirun.front().empty()), "--mpirun: the MPI launcher is empty");
  need(!p.out_dir.empty(), "--out: the experiment needs a folder");
  need(!p.arms.empty(), "--arms: the experiment needs at least one arm");
  for (size_t i = 0; i < p.arms.size(); ++i)
    for (size_t j = 0; j < i; ++j) need(p.arms[i] != p.arms[j], "--arms: " + arm_name(p.arms[i]) + " is given twice");
  for (const auto& kv : p.sets) {
    nlohmann::json j;
    try {
      j = config_assignment(kv);
      config_from_json(j);
    } catch (const ConfigError& e) {
      throw std::invalid_argument(std::string("--set ") + kv + ": " + e.what());
    }
    const std::string key = kv.substr(0, kv.find('='));
    for (const char* own :
         {"regime", "seed", "generations", "neat", "neat.population", "neat.initial_links", "sim", "sim.steps"})
      need(key != own, "--set " + kv + ": " + key + " is the experiment's own (use its option, or its arms)");
  }
}

std::vector<Trial> plan_trials(const ExperimentParams& p) {
  validate_experiment(p);
  std::vector<Trial> out;
  for (int k = 1; k <= p.trials; ++k)
    for (Arm a : p.arms) {
      Trial t;
      t.arm = a;
      t.regime = arm_regime(a);
      t.number = k;
      t.seed = trial_seed(a, k);
      t.log_path = p.out_dir + "/" + t.name() + ".lcmlog";
      t.output_path = p.out_dir + "/" + t.name() + ".out";
      out.push_back(t);
    }
  return out;
}

std::vector<std::string> evolve_arguments(const Trial& t, const ExperimentParams& p, bool resume) {
  // The sizes go on the command line on resume too: robozoo-evolve takes the run's
  // configuration, its evaluator's included, from the checkpoint; the command line
  // states the same sizes, which the plan has checked against the checkpoint.
  std::vector<std::string> a = {"--log",
                                t.log_path,
                                "--quiet",
                                "--regime",
                                regime_name(t.regime),
                                "--seed",
                                std::to_string(t.seed),
                                "--population",
                                std::to_string(p.population),
                                "--generations",
                                std::to_string(p.generations),
                                "--run-id",
                                t.name()};
  if (arm_initial_links(t.arm) != NeatParams{}.initial_links)
    a.insert(a.end(), {"--set", "neat.initial_links=" + initial_links_name(arm_initial_links(t.arm))});
  for (const auto& kv : p.sets) a.insert(a.end(), {"--set", kv});
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
