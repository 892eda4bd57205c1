#include "evolve/neat/initial_genome.hpp"

#include <stdexcept>
#include <string>

namespace robozoo {

int64_t initial_link_innovation(const GenomeLayout& layout, int input, int output) {
  return static_cast<int64_t>(input) * layout.num_outputs + output;
}

int64_t first_free_innovation(const GenomeLayout& layout) {
  return static_cast<int64_t>(layout.num_inputs) * layout.num_outputs;
}

Genome initial_genome(const GenomeLayout& layout, int64_t id, const NeatParams& p, Rng& rng) {
  if (layout.num_inputs < 1 || layout.num_outputs < 1)
    throw std::invalid_argument("genome layout needs at least one input and one output, got " +
                                std::to_string(layout.num_inputs) + " and " +
                                std::to_string(layout.num_outputs));
  if (layout.bias_input >= layout.num_inputs || layout.bias_input < -1)
    throw std::invalid_argument("genome layout: bias input " + std::to_string(layout.bias_input) +
                                " is not an input");
  Genome g;
  g.id = id;
  for (int i = 0; i < layout.num_inputs; ++i)
    g.nodes.push_back({i, i == layout.bias_input ? NodeKind::Bias : NodeKind::Input,
                       Activation::Linear});
  for (int o = 0; o < layout.num_outputs; ++o)
    g.nodes.push_back({layout.num_inputs + o, NodeKind::Output, layout.output_activation});
  const double r = p.initial_weight_range;
  for (int i = 0; i < layout.num_inputs; ++i)
    for (int o = 0; o < layout.num_outputs; ++o) {
      LinkGene l;
      l.innovation = initial_link_innovation(layout, i, o);
      l.from = i;
      l.to = layout.num_inputs + o;
      l.weight = rng.uniform(-r, r);
      l.enabled = true;
      l.born = 0;
      g.links.push_back(l);
    }
  return g;
}

}  // namespace robozoo
