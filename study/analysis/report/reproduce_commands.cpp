#include "study/analysis/report/reproduce_commands.hpp"

#include <algorithm>
#include <stdexcept>

#include "study/experiment/trial_plan.hpp"

namespace robozoo {

namespace {

// What one arm's runs have in common, and whether robozoo-experiment makes them.
struct ArmRuns {
  std::string arm;
  std::vector<const RunAnalysis*> runs;  ///< by seed
  bool known = false;                    ///< this robozoo knows the arm
  bool uniform = false;                  ///< every run has the same population, generations, steps
  bool planned = false;                  ///< uniform and seeds trial_seed(arm, 1..N)
};

ArmRuns arm_runs(const std::string& arm, const std::vector<RunAnalysis>& side) {
  ArmRuns r;
  r.arm = arm;
  for (const auto& x : side) r.runs.push_back(&x);
  std::sort(r.runs.begin(), r.runs.end(), [](const RunAnalysis* a, const RunAnalysis* b) { return a->seed < b->seed; });
  Arm id{};
  try {
    id = arm_from_name(arm);
    r.known = true;
  } catch (const std::invalid_argument&) {
    return r;
  }
  r.uniform = !r.runs.empty();
  for (const auto* x : r.runs)
    r.uniform = r.uniform && x->population == r.runs[0]->population &&
                x->generations_requested == r.runs[0]->generations_requested && x->steps == r.runs[0]->steps;
  r.planned = r.uniform;
  for (size_t k = 0; k < r.runs.size() && r.planned; ++k)
    r.planned = r.runs[k]->seed == trial_seed(id, static_cast<int>(k) + 1);
  return r;
}

std::string sizes(const RunAnalysis& r) {
  std::string s =
      " --generations " + std::to_string(r.generations_requested) + " --population " + std::to_string(r.population);
  if (r.steps > 0 && r.steps != 2500) s += " --steps " + std::to_string(r.steps);
  return s;
}

std::string experiment_line(const std::string& arms, size_t trials, const RunAnalysis& r, const std::string& dir) {
  return "build/bin/robozoo-experiment --trials " + std::to_string(trials) + " --arms " + arms + sizes(r) + " --out " +
         dir;
}

void per_run_lines(const ArmRuns& a, const std::string& dir, std::vector<std::string>& out) {
  out.push_back("# " + a.arm + ": seeds other than robozoo-experiment's trials 1.." + std::to_string(a.runs.size()) +
                " (or runs of different sizes): one robozoo-evolve per run");
  if (!a.known) {
    out.push_back("# (this robozoo does not know the arm " + a.arm + ")");
    return;
  }
  for (const auto* r : a.runs) {
    Trial t;
    t.arm = arm_from_name(a.arm);
    t.regime = arm_regime(t.arm);
    t.seed = r->seed;
    t.log_path = dir + "/" + t.name() + ".lcmlog";
    ExperimentParams p;
    p.population = r->population;
    p.generations = r->generations_requested;
    p.steps = r->steps;
    std::string line = "build/bin/robozoo-evolve";
    for (const auto& arg : evolve_arguments(t, p, false)) line += " " + arg;
    out.push_back(line);
  }
}

}  // namespace

std::vector<std::string> reproduce_commands(const ExperimentAnalysis& a, const std::string& log_dir,
                                            const std::string& stats_command) {
  std::vector<std::string> out;
  const ArmRuns c = arm_runs(a.control_arm, a.control), x = arm_runs(a.experimental_arm, a.experimental);
  out.push_back("# the runs compared here (arms, trials, sizes and seeds as found in the logs)");
  const bool together =
      c.planned && x.planned && c.runs.size() == x.runs.size() && sizes(*c.runs[0]) == sizes(*x.runs[0]);
  if (together) {
    out.push_back(experiment_line(a.control_arm + "," + a.experimental_arm, c.runs.size(), *c.runs[0], log_dir));
  } else {
    for (const ArmRuns* arm : {&c, &x}) {
      if (arm->runs.empty()) continue;
      if (arm->planned)
        out.push_back(experiment_line(arm->arm, arm->runs.size(), *arm->runs[0], log_dir));
      else
        per_run_lines(*arm, log_dir, out);
    }
  }
  out.push_back(stats_command);
  out.push_back("# not run: the paper's full size (30 trials per arm, population 150, 500 generations)");
  out.push_back("build/bin/robozoo-experiment --trials 30 --arms " + a.control_arm + "," + a.experimental_arm +
                " --generations 500 --population 150 --out runs/paper");
  return out;
}

}  // namespace robozoo
