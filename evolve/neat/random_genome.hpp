#pragma once
// Random genomes as evolution makes them: an initial genome (every input linked
// to every output) followed by rounds of NEAT mutations. Used to look at single
// robots (robozoo-evolve eval) and by the benchmark, so that the genomes grow
// real robots rather than the root alone.
#include "evolve/core/rng.hpp"
#include "evolve/cppn/genome.hpp"
#include "evolve/neat/params.hpp"

namespace robozoo {

struct RandomGenomeParams {
  int rounds = 10;                  ///< mutation rounds (count)
  double add_node_probability = 0.5;///< per round
  double add_link_probability = 0.5;///< per round
  /// Start from fully_recurrent_genome instead of initial_genome (recurrent regime
  /// only): every recurrent CPPN then has cycles from the first round.
  bool fully_recurrent_start = false;
};

/// A fully recurrent start: initial_genome (every input linked to every output)
/// plus a link from every output to every other output (no self-loops), innovations
/// first_free_innovation(layout) + k in (from, to) order, weights uniform in
/// [-initial_weight_range, initial_weight_range). For the robot layout: 99 + 110 =
/// 209 links, with cycles through every output. A stand-in for benchmarks and tests
/// of the recurrent regime's fully recurrent start until NEAT itself makes it.
Genome fully_recurrent_genome(const GenomeLayout& layout, int64_t id, const NeatParams& neat, Rng& rng);
/// First innovation number free for mutations after fully_recurrent_genome.
int64_t first_free_innovation_fully_recurrent(const GenomeLayout& layout);

/// Deterministic in rng. Regime decides which links add-link may create. Throws
/// std::invalid_argument for a fully recurrent start in the feed-forward regime.
Genome random_evolved_genome(const GenomeLayout& layout, Regime regime, const NeatParams& neat,
                             const RandomGenomeParams& params, Rng& rng, int64_t id = 0);

}  // namespace robozoo
