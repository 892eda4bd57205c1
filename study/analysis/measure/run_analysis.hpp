#pragma once
// Everything the experiment's statistics use from one run, computed from its
// summary: the best-so-far fitness curve, the best-of-run robot's body-plan and
// CPPN statistics, and the run's champion changes. Small enough to keep for
// every run of an experiment while the logs are read one at a time.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "study/analysis/measure/champion_changes.hpp"
#include "study/analysis/measure/genotype_stats.hpp"
#include "study/analysis/measure/morphology_stats.hpp"
#include "evolve/record/run_summary.hpp"

namespace robozoo {

struct AnalysisParams {
  MorphologyStatsParams morphology;  ///< ground contact tolerance
  ChampionChangeParams changes;      ///< topology options, which changes count
};

struct RunAnalysis {
  std::string path;
  std::string run_id;
  int8_t regime = 0;                ///< 0 feed-forward (control), 1 recurrent (experimental)
  std::string arm = "feedforward";  ///< experiment arm (feedforward, recurrent, recurrent-sparse)
  int32_t max_spheres = 0;          ///< growth.max_spheres of the run (count; 0 if unknown)
  double max_d = 0;                 ///< the largest d of any logged genome of the run (m)
  double target_distance = 0;       ///< distance from the origin to the target (m; 0 if unknown)
  /// Per generation, the share of each outcome (generation_t counts / population).
  std::vector<std::array<double, 6>> outcome_shares;
  int64_t seed = 0;
  int32_t population = 0;             ///< (count)
  int32_t generations_requested = 0;  ///< (count)
  int32_t steps = 0;                  ///< physics steps per evaluation (count)
  bool complete = false;              ///< every requested generation is in the log
  int64_t undecodable = 0;            ///< messages skipped (count)
  std::vector<double> best_so_far;    ///< best-so-far fitness per logged generation (fitness units)

  bool has_best = false;        ///< a best-of-run champion with its morphology was logged
  int32_t best_generation = 0;  ///< generation it first became champion
  int64_t best_genome_id = -1;
  double best_fitness = 0;     ///< fitness units
  int8_t best_outcome = 0;     ///< cppn_genome_t outcome code
  MorphologyStats morphology;  ///< of the best-of-run robot (ground: from its pose stream, if any)
  GenotypeStats genotype;      ///< of the best-of-run CPPN
  ChampionChanges changes;     ///< the run's new champions
};

/// Analyses one run. Throws std::invalid_argument for a malformed best-of-run
/// morphology or genome (naming the log).
RunAnalysis analyze_run(const RunSummary& run, const AnalysisParams& params = {});

}  // namespace robozoo
