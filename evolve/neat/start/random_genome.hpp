#pragma once
// Random genomes as evolution makes them: the regime's initial genome followed by rounds of NEAT mutations. Used to look at single
// robots (robozoo-evolve eval) and by the benchmark, so that the genomes grow
// real robots rather than the root alone.
#include "evolve/core/rng.hpp"
#include "evolve/cppn/genome.hpp"
#include "evolve/neat/params.hpp"

namespace robozoo {

struct RandomGenomeParams {
  int rounds = 10;                    ///< mutation rounds (count)
  double add_node_probability = 0.5;  ///< per round
  double add_link_probability = 0.5;  ///< per round
};

/// Deterministic in rng. Regime decides which links add-link may create.
Genome random_evolved_genome(const GenomeLayout& layout, Regime regime, const NeatParams& neat,
                             const RandomGenomeParams& params, Rng& rng, int64_t id = 0);

}  // namespace robozoo
