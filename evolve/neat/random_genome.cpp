#include "evolve/neat/random_genome.hpp"

#include "evolve/neat/initial_genome.hpp"
#include "evolve/neat/innovation.hpp"
#include "evolve/neat/mutation.hpp"

#include <stdexcept>

namespace robozoo {

int64_t first_free_innovation_fully_recurrent(const GenomeLayout& layout) {
  return first_free_innovation(layout) + static_cast<int64_t>(layout.num_outputs) * (layout.num_outputs - 1);
}

Genome fully_recurrent_genome(const GenomeLayout& layout, int64_t id, const NeatParams& neat, Rng& rng) {
  Genome g = initial_genome(layout, id, neat, rng);
  int64_t innovation = first_free_innovation(layout);
  const double r = neat.initial_weight_range;
  for (int from = 0; from < layout.num_outputs; ++from)
    for (int to = 0; to < layout.num_outputs; ++to) {
      if (from == to) continue;
      LinkGene l;
      l.innovation = innovation++;
      l.from = layout.num_inputs + from;
      l.to = layout.num_inputs + to;
      l.weight = rng.uniform(-r, r);
      g.links.push_back(l);
    }
  return g;
}

Genome random_evolved_genome(const GenomeLayout& layout, Regime regime, const NeatParams& neat,
                             const RandomGenomeParams& params, Rng& rng, int64_t id) {
  if (params.fully_recurrent_start && regime != Regime::Recurrent)
    throw std::invalid_argument("a fully recurrent start needs the recurrent regime");
  Genome g = params.fully_recurrent_start ? fully_recurrent_genome(layout, id, neat, rng)
                                          : initial_genome(layout, id, neat, rng);
  InnovationTracker innov(params.fully_recurrent_start ? first_free_innovation_fully_recurrent(layout)
                                                       : first_free_innovation(layout),
                          layout.first_hidden());
  for (int round = 0; round < params.rounds; ++round) {
    innov.new_generation();
    if (rng.bernoulli(params.add_node_probability)) mutate_add_node(g, neat, innov, round, rng);
    if (rng.bernoulli(params.add_link_probability)) mutate_add_link(g, regime, layout, neat, innov, round, rng);
    mutate_weights(g, neat, round, rng);
  }
  return g;
}

}  // namespace robozoo
