#include "evolve/neat/start/random_genome.hpp"

#include "evolve/neat/start/initial_genome.hpp"
#include "evolve/neat/variation/innovation.hpp"
#include "evolve/neat/variation/mutation.hpp"

namespace robozoo {

Genome random_evolved_genome(const GenomeLayout& layout, Regime regime, const NeatParams& neat,
                             const RandomGenomeParams& params, Rng& rng, int64_t id) {
  Genome g = initial_genome(layout, id, neat, regime, rng);
  InnovationTracker innov(first_free_innovation(layout), layout.first_hidden());
  for (int round = 0; round < params.rounds; ++round) {
    innov.new_generation();
    if (rng.bernoulli(params.add_node_probability)) mutate_add_node(g, neat, innov, round, rng);
    if (rng.bernoulli(params.add_link_probability)) mutate_add_link(g, regime, layout, neat, innov, round, rng);
    mutate_weights(g, neat, round, rng);
  }
  return g;
}

}  // namespace robozoo
