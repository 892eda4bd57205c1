#include "study/analysis/measure/run_analysis.hpp"

#include <stdexcept>

namespace robozoo {

RunAnalysis analyze_run(const RunSummary& run, const AnalysisParams& params) {
  RunAnalysis a;
  a.path = run.path;
  a.run_id = run.run_id;
  a.regime = run.regime;
  a.arm = run.arm;
  a.max_spheres = run.max_spheres;
  a.max_d = run.max_d;
  a.target_distance = run.target_distance;
  for (const auto& g : run.generations) {
    std::array<double, 6> share{};
    double n = 0;
    for (int32_t k : g.outcomes) n += k;
    for (size_t k = 0; k < share.size(); ++k) share[k] = n > 0 ? g.outcomes[k] / n : 0.0;
    a.outcome_shares.push_back(share);
  }
  a.seed = run.seed;
  a.population = run.population;
  a.generations_requested = run.generations_requested;
  a.steps = run.steps;
  a.complete = run.complete();
  a.undecodable = run.undecodable;
  for (const auto& g : run.generations) a.best_so_far.push_back(g.best_so_far_fitness);
  try {
    const ChampionRecord* best = best_of_run(run);
    if (best && best->has_morphology) {
      a.has_best = true;
      a.best_generation = best->generation;
      a.best_genome_id = best->genome.genome_id;
      a.best_fitness = best->genome.fitness;
      a.best_outcome = best->genome.outcome;
      const auto poses = run.min_center_z.find(best->genome.genome_id);
      a.morphology = morphology_stats(best->morphology, poses == run.min_center_z.end() ? nullptr : &poses->second,
                                      params.morphology);
      a.genotype = genotype_stats(best->genome);
    }
    a.changes = champion_changes(run, params.changes);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(run.path + ": " + e.what());
  }
  return a;
}

}  // namespace robozoo
