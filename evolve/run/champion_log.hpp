#pragma once
// A compact result's best-of-run champion as a log that robozoo-render,
// robozoo-replay and robozoo-view read: the champion grown, evaluated and
// simulated again by this build, written as the one generation of a
// one-generation run (run_t with the result's configuration, generations 1;
// generation_t with the counts of the generation the champion won; its genome
// with the committed fitness, r, d and outcome; its morphology; its pose
// stream). Its generation is 0 in that log; its run id, genome id and species
// are the result's.
#include <string>

#include "evolve/run/run_results.hpp"

namespace robozoo {

struct ChampionLogInfo {
  int32_t generation = 0;  ///< generation the champion won in its run
  int64_t genome_id = -1;
  double fitness = 0;  ///< committed fitness (fitness units)
  size_t poses = 0;    ///< poses written (count)
};

/// Writes the log at `log_path`. Throws std::invalid_argument when the result
/// has no best-of-run champion or its configuration cannot be read, and
/// std::runtime_error when this build does not reproduce the committed
/// fitness, r, d or outcome (naming both values) or the log cannot be written.
ChampionLogInfo write_champion_log(const RunResults& results, const std::string& log_path);

}  // namespace robozoo
