// robozoo-xor: the NEAT core's proof on XOR (the NEAT paper's benchmark).
//
// For each run r (seed S + r) and each regime (feed-forward first, then
// recurrent), CPPN-NEAT with a preset's parameters (the project's defaults, or
// the NEAT paper's own: evolve/neat/xor/xor_presets.hpp) evolves XOR networks
// (evolve/neat/xor/xor_task.hpp) until some genome solves it or the generation
// cap is reached (a failure).
//
// Evaluations: the default preset counts every genome evaluated up to and
// including the generation in which a solution first appears, (g + 1) *
// population for a solution in generation g (the first generation is 0); the
// neat-paper preset counts as the NEAT paper does ("networks evaluated" until
// the solution; Stanley's xor_test adds the winner's number to the genomes of
// the earlier generations): g * population + the position (from 1) of the first
// solver in the solving generation. Both counts are in the JSON. Unchanged elite
// copies are evaluated and counted like any genome. The reported solution is the
// fittest solver of that generation (the first in population order on ties).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "evolve/config/run_config.hpp"
#include "evolve/core/rng.hpp"
#include "evolve/neat/population.hpp"
#include "evolve/neat/xor/xor_presets.hpp"
#include "evolve/neat/xor/xor_task.hpp"
#include "evolve/core/version.hpp"
#include "util/parse_options.hpp"

namespace {

using robozoo::Regime;

struct RunResult {
  int64_t seed = 0;
  bool solved = false;
  int generation = -1;                 // generation of the first solution
  int64_t evaluations = 0;             // the preset's count (see above)
  int64_t generation_evaluations = 0;  // genomes evaluated up to and including that generation
  int64_t solver_evaluations = 0;      // genomes evaluated up to and including the first solver
  int hidden = 0;                      // hidden nodes of the solution
  int enabled_links = 0;               // enabled links of the solution
  int species = 0;                     // species in the solving generation
};

RunResult run_once(const robozoo::NeatParams& params, const robozoo::XorPreset& preset, Regime regime, int64_t seed,
                   int cap) {
  const robozoo::GenomeLayout& layout = preset.layout;
  robozoo::Rng rng(static_cast<uint64_t>(seed));
  robozoo::Population pop(params, regime, layout, rng);
  RunResult r;
  r.seed = seed;
  int64_t evaluations = 0;
  std::vector<double> fitness;
  for (int gen = 0; gen < cap; ++gen) {
    const auto& genomes = pop.genomes();
    fitness.assign(genomes.size(), 0.0);
    int best_solver = -1, first_solver = -1;
    for (size_t i = 0; i < genomes.size(); ++i) {
      const robozoo::XorResult x = robozoo::evaluate_xor(genomes[i], layout, preset.rules);
      fitness[i] = x.fitness;
      if (x.solved && first_solver < 0) first_solver = static_cast<int>(i);
      if (x.solved && (best_solver < 0 || x.fitness > fitness[static_cast<size_t>(best_solver)]))
        best_solver = static_cast<int>(i);
    }
    const int64_t before = evaluations;
    evaluations += static_cast<int64_t>(genomes.size());
    if (best_solver >= 0) {
      const auto& g = genomes[static_cast<size_t>(best_solver)];
      r.solved = true;
      r.generation = gen;
      r.generation_evaluations = evaluations;
      r.solver_evaluations = before + first_solver + 1;
      r.evaluations = preset.count_to_solver ? r.solver_evaluations : r.generation_evaluations;
      r.hidden = robozoo::count_hidden(g);
      r.enabled_links = robozoo::count_enabled_links(g);
      r.species = static_cast<int>(pop.species().size());
      return r;
    }
    pop.advance(fitness, rng);
  }
  r.evaluations = r.generation_evaluations = r.solver_evaluations = evaluations;
  return r;
}

struct Summary {
  std::string regime;
  int runs = 0, solved = 0;
  double evals_mean = 0, evals_std = 0, evals_min = 0, evals_max = 0;
  double gen_evals_mean = 0, gen_evals_std = 0, solver_evals_mean = 0, solver_evals_std = 0;
  double gens_mean = 0, hidden_mean = 0, links_mean = 0;
  double wall_s = 0;
  std::vector<RunResult> per_run;
};

// Mean and sample standard deviation (n - 1, as the NEAT paper's spread is read).
void mean_std(const std::vector<double>& v, double& mean, double& std) {
  mean = std = 0.0;
  if (v.empty()) return;
  const double n = static_cast<double>(v.size());
  double sum = 0, sum2 = 0;
  for (double x : v) {
    sum += x;
    sum2 += x * x;
  }
  mean = sum / n;
  std = v.size() > 1 ? std::sqrt(std::max(0.0, (sum2 - n * mean * mean) / (n - 1))) : 0.0;
}

Summary summarise(const std::string& name, const std::vector<RunResult>& rs, double wall) {
  Summary s;
  s.regime = name;
  s.runs = static_cast<int>(rs.size());
  s.wall_s = wall;
  s.per_run = rs;
  std::vector<double> evals, gen_evals, solver_evals;
  double gens = 0, hidden = 0, links = 0;
  for (const auto& r : rs) {
    if (!r.solved) continue;
    ++s.solved;
    evals.push_back(static_cast<double>(r.evaluations));
    gen_evals.push_back(static_cast<double>(r.generation_evaluations));
    solver_evals.push_back(static_cast<double>(r.solver_evaluations));
    gens += r.generation;
    hidden += r.hidden;
    links += r.enabled_links;
  }
  if (s.solved > 0) {
    const double n = s.solved;
    mean_std(evals, s.evals_mean, s.evals_std);
    mean_std(gen_evals, s.gen_evals_mean, s.gen_evals_std);
    mean_std(solver_evals, s.solver_evals_mean, s.solver_evals_std);
    s.evals_min = *std::min_element(evals.begin(), evals.end());
    s.evals_max = *std::max_element(evals.begin(), evals.end());
    s.gens_mean = gens / n;
    s.hidden_mean = hidden / n;
    s.links_mean = links / n;
  }
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "robozoo-xor: CPPN-NEAT on XOR, feed-forward then recurrent regime. Presets: 'default' (the "
      "project's NEAT: HyperNEAT's defaults and topology rules; output signed sigmoid mapped to "
      "(out+1)/2) and 'neat-paper' (the NEAT paper's own XOR parameters: steepened sigmoid "
      "1/(1+e^(-4.9x)), c1 = c2 = 1, c3 = 0.4, fixed threshold 3.0, classic add-node, disabled "
      "genes inherited disabled with p 0.75, interspecies mating 0.001, classic topology rules, and "
      "where the paper is silent the mechanics and XOR evaluation of Stanley's own NEAT C++). "
      "Inputs x1, x2 in {0,1} and bias 1.0; fitness (4 - sum|err|)^2; solved when all four patterns "
      "are on the right side of 0.5. Evaluations to solve: default, genomes evaluated up to and "
      "including the generation where a solution first appears; neat-paper, up to and including "
      "the first solver (the NEAT paper's count). The JSON has both."};
  int runs = 100;
  int64_t seed = 1;
  int generations = 1000;
  int population = 150;
  bool as_json = false;
  unsigned hidden_activations = 0;
  std::string preset_name = "default";
  std::string hidden = "";
  app.add_option("--runs", runs, "independent runs per regime (run r uses seed S + r)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--seed", seed, "seed S of the first run")->capture_default_str();
  app.add_option("--generations", generations, "generation cap; a run without a solution by then fails")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--population", population, "population size")->check(CLI::Range(2, 1000000))->capture_default_str();
  app.add_option("--preset", preset_name, "parameter set: default or neat-paper")
      ->check(CLI::IsMember(robozoo::xor_preset_names()))
      ->capture_default_str();
  auto* hidden_opt = app.add_option("--hidden", hidden,
                                    "activations a new hidden node may get: 'sigmoid' (the preset's sigmoid only) "
                                    "or 'all' (its sigmoid, signed cosine, Gaussian); default: the preset's own "
                                    "(default: all, neat-paper: sigmoid)")
                         ->check(CLI::IsMember({"sigmoid", "all"}));
  app.add_option("--hidden-activations", hidden_activations,
                 "bit mask of the activations a new hidden node may get (bit 0 signed sigmoid, "
                 "1 signed cosine, 2 Gaussian, 3 linear, 4 sine, 5 steepened sigmoid)")
      ->check(CLI::Range(1u, (1u << robozoo::kNumActivations) - 1u))
      ->excludes(hidden_opt);
  std::vector<std::string> sets;
  app.add_option("--set", sets,
                 "change one NEAT parameter of the preset: neat.KEY=VALUE as robozoo-evolve's --set (e.g. "
                 "neat.weight_limit=8); repeatable")
      ->take_all();
  app.add_flag("--json", as_json, "print the results as JSON instead of a table");
  app.set_version_flag("--version", robozoo::version_line());
  if (const auto stop = robozoo::parse_options(app, argc, argv, "robozoo-xor")) return *stop;

  const robozoo::XorPreset preset = robozoo::xor_preset(preset_name);
  robozoo::NeatParams params = preset.params;
  params.population = population;
  if (hidden == "sigmoid") params.hidden_activations = preset.sigmoid_only;
  if (hidden == "all") params.hidden_activations = preset.all_three;
  if (hidden_activations != 0) params.hidden_activations = hidden_activations;
  try {
    robozoo::RunConfig c;
    c.neat = params;
    for (const auto& kv : sets) {
      if (kv.rfind("neat.", 0) != 0) throw robozoo::ConfigError("--set " + kv + ": only neat.* keys apply to XOR");
      c = robozoo::config_from_json(robozoo::config_assignment(kv), c);
    }
    params = c.neat;
    robozoo::validate_neat_params(params);
  } catch (const std::exception& e) {
    std::cerr << "robozoo-xor: " << e.what() << "\n";
    return 2;
  }

  std::vector<Summary> summaries;
  for (Regime regime : {Regime::FeedForward, Regime::Recurrent}) {
    const std::string name = regime == Regime::FeedForward ? "feedforward" : "recurrent";
    std::vector<RunResult> results;
    const auto t0 = std::chrono::steady_clock::now();
    for (int r = 0; r < runs; ++r) {
      const RunResult res = run_once(params, preset, regime, seed + r, generations);
      std::cerr << name << " run " << r + 1 << "/" << runs << " seed " << res.seed << ": "
                << (res.solved ? "solved in generation " + std::to_string(res.generation) + ", " +
                                     std::to_string(res.evaluations) + " evaluations, " + std::to_string(res.hidden) +
                                     " hidden, " + std::to_string(res.enabled_links) + " links"
                               : "not solved in " + std::to_string(generations) + " generations")
                << "\n";
      results.push_back(res);
    }
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    summaries.push_back(summarise(name, results, wall));
  }

  if (as_json) {
    nlohmann::json j;
    j["runs"] = runs;
    j["seed"] = seed;
    j["population"] = population;
    j["generation_cap"] = generations;
    j["preset"] = preset_name;
    j["set"] = sets;
    j["hidden_activations"] = params.hidden_activations;
    j["neat_paper_evaluations_mean"] = 4755;
    j["evaluations_counted_as"] =
        preset.count_to_solver
            ? "genomes evaluated up to and including the first solver, in population order (the NEAT paper's count)"
            : "genomes evaluated up to and including the generation of the first solution";
    j["stanley_activation"] = preset.rules.stanley_activation;
    j["regimes"] = nlohmann::json::array();
    for (const auto& s : summaries) {
      nlohmann::json per = nlohmann::json::array();
      for (const auto& r : s.per_run)
        per.push_back({{"seed", r.seed},
                       {"solved", r.solved},
                       {"generation", r.generation},
                       {"evaluations", r.evaluations},
                       {"generation_evaluations", r.generation_evaluations},
                       {"solver_evaluations", r.solver_evaluations},
                       {"hidden", r.hidden},
                       {"enabled_links", r.enabled_links},
                       {"species", r.species}});
      j["regimes"].push_back({{"regime", s.regime},
                              {"runs", s.runs},
                              {"solved", s.solved},
                              {"evaluations_mean", s.evals_mean},
                              {"evaluations_std", s.evals_std},
                              {"evaluations_min", s.evals_min},
                              {"evaluations_max", s.evals_max},
                              {"generation_evaluations_mean", s.gen_evals_mean},
                              {"generation_evaluations_std", s.gen_evals_std},
                              {"solver_evaluations_mean", s.solver_evals_mean},
                              {"solver_evaluations_std", s.solver_evals_std},
                              {"generations_mean", s.gens_mean},
                              {"hidden_mean", s.hidden_mean},
                              {"enabled_links_mean", s.links_mean},
                              {"wall_seconds", s.wall_s},
                              {"per_run", per}});
    }
    std::cout << j.dump(2) << "\n";
    return 0;
  }
  std::cout
      << "XOR, preset " << preset_name << ", population " << population << ", generation cap " << generations
      << ", seeds " << seed << ".." << seed + runs - 1 << ", hidden activations mask " << params.hidden_activations
      << "\n"
      << (preset.count_to_solver
              ? "evaluations = genomes evaluated up to and including the first solver (the NEAT paper's count)\n\n"
              : "evaluations = genomes evaluated up to and including the solving generation\n\n");
  std::cout << std::left << std::setw(12) << "regime" << std::right << std::setw(9) << "solved" << std::setw(11)
            << "evals" << std::setw(9) << "std" << std::setw(8) << "min" << std::setw(8) << "max" << std::setw(8)
            << "gens" << std::setw(8) << "hidden" << std::setw(8) << "links" << std::setw(9) << "wall_s"
            << "\n";
  for (const auto& s : summaries) {
    std::cout << std::left << std::setw(12) << s.regime << std::right << std::setw(9)
              << (std::to_string(s.solved) + "/" + std::to_string(s.runs)) << std::fixed << std::setprecision(0)
              << std::setw(11) << s.evals_mean << std::setw(9) << s.evals_std << std::setw(8) << s.evals_min
              << std::setw(8) << s.evals_max << std::setprecision(1) << std::setw(8) << s.gens_mean
              << std::setprecision(2) << std::setw(8) << s.hidden_mean << std::setw(8) << s.links_mean
              << std::setprecision(1) << std::setw(9) << s.wall_s << "\n";
  }
  std::cout << "(NEAT paper, feed-forward: 100/100 solved, 4,755 evaluations mean, std 2,553, "
               "2.35 hidden nodes)\n";
  return 0;
}
