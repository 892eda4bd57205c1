#include "evolve/neat/start/initial_genome.hpp"

#include <stdexcept>
#include <string>

namespace robozoo {

int64_t initial_link_innovation(const GenomeLayout& layout, int from, int output) {
  return static_cast<int64_t>(from) * layout.num_outputs + output;
}

int64_t first_free_innovation(const GenomeLayout& layout) {
  return static_cast<int64_t>(layout.num_inputs + layout.num_outputs) * layout.num_outputs;
}

bool link_allowed_by_positions(const NodeGene& from, const NodeGene& to, Regime regime, const NeatParams& p) {
  if (to.kind == NodeKind::Input || to.kind == NodeKind::Bias) return false;
  if (from.id == to.id) return regime == Regime::Recurrent && p.self_loops;
  if (regime == Regime::Recurrent) return true;
  return from.position < to.position;
}

Genome initial_genome(const GenomeLayout& layout, int64_t id, const NeatParams& p, Regime regime, Rng& rng) {
  if (layout.num_inputs < 1 || layout.num_outputs < 1)
    throw std::invalid_argument("genome layout needs at least one input and one output, got " +
                                std::to_string(layout.num_inputs) + " and " + std::to_string(layout.num_outputs));
  if (layout.bias_input >= layout.num_inputs || layout.bias_input < -1)
    throw std::invalid_argument("genome layout: bias input " + std::to_string(layout.bias_input) + " is not an input");
  Genome g;
  g.id = id;
  for (int i = 0; i < layout.num_inputs; ++i)
    g.nodes.push_back(
        {i, i == layout.bias_input ? NodeKind::Bias : NodeKind::Input, Activation::Linear, kInputPosition});
  for (int o = 0; o < layout.num_outputs; ++o)
    g.nodes.push_back({layout.num_inputs + o, NodeKind::Output, layout.output_activation, kOutputPosition});
  const double r = p.initial_weight_range;
  const bool zero_recurrent = p.initial_links == InitialLinks::AllAllowedRecurrentZero;
  const int sources =
      p.initial_links == InitialLinks::InputsToOutputs ? layout.num_inputs : layout.num_inputs + layout.num_outputs;
  for (int from = 0; from < sources; ++from)
    for (int o = 0; o < layout.num_outputs; ++o) {
      const NodeGene& a = g.nodes[static_cast<size_t>(from)];
      const NodeGene& b = g.nodes[static_cast<size_t>(layout.num_inputs + o)];
      if (!link_allowed_by_positions(a, b, regime, p)) continue;
      LinkGene l;
      l.innovation = initial_link_innovation(layout, from, o);
      l.from = a.id;
      l.to = b.id;
      l.weight = rng.uniform(-r, r);  // drawn in every mode, so the draws match AllAllowed's
      if (zero_recurrent && from >= layout.num_inputs) l.weight = 0.0;
      l.enabled = true;
      l.born = 0;
      g.links.push_back(l);
    }
  return g;
}

}  // namespace robozoo
