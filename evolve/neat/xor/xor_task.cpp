#include "evolve/neat/xor/xor_task.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>
#include <string>

#include "evolve/cppn/network.hpp"

namespace robozoo {

GenomeLayout xor_layout(Activation output) {
  GenomeLayout l;
  l.num_inputs = 3;
  l.bias_input = 2;
  l.num_outputs = 1;
  l.output_activation = output;
  return l;
}

namespace {

// Stanley's activation as a genome the project's network reads the same way: every enabled link
// leaving a non-input node that no input reaches through enabled links is disabled (such a node
// outputs 0). `output_reached` tells whether some input reaches the output.
Genome silence_unreached(const Genome& g, const GenomeLayout& layout, bool& output_reached) {
  std::set<int32_t> reached;
  for (const auto& n : g.nodes)
    if (n.kind == NodeKind::Input || n.kind == NodeKind::Bias) reached.insert(n.id);
  for (bool grew = true; grew;) {
    grew = false;
    for (const auto& l : g.links)
      if (l.enabled && reached.count(l.from) && reached.insert(l.to).second) grew = true;
  }
  output_reached = reached.count(layout.num_inputs) > 0;  // the output is node num_inputs
  Genome s = g;
  for (auto& l : s.links)
    if (!reached.count(l.from)) l.enabled = false;
  return s;
}

}  // namespace

XorResult evaluate_xor(const Genome& g, const GenomeLayout& layout, const XorRules& rules) {
  const bool signed_output = layout.output_activation == Activation::SignedSigmoid;
  if (!signed_output && layout.output_activation != Activation::SteepenedSigmoid)
    throw std::invalid_argument("evaluate_xor: the output must be a signed or steepened sigmoid, not " +
                                activation_name(layout.output_activation));
  XorResult r;
  bool output_reached = true;
  const Genome read = rules.stanley_activation ? silence_unreached(g, layout, output_reached) : g;
  if (!output_reached) {
    validate_genome(g, layout);
    r.fitness = 0.001;  // Stanley's flawed network
    return r;
  }
  // Stanley relaxes an acyclic network completely; the project's network does so in one exact
  // pass when it has at least as many updates as the longest path (< number of nodes).
  const int updates =
      rules.stanley_activation && !has_cycle(read) ? std::max(10, static_cast<int>(read.nodes.size())) : 10;
  Network net(read, layout, updates);
  static constexpr double kIn[4][2] = {{0, 0}, {0, 1}, {1, 0}, {1, 1}};
  static constexpr double kTarget[4] = {0, 1, 1, 0};
  double error = 0.0;
  r.solved = true;
  for (int k = 0; k < 4; ++k) {
    const double in[3] = {kIn[k][0], kIn[k][1], 1.0};
    double out = 0.0;
    net.query(in, &out);
    const double y = signed_output ? (out + 1.0) / 2.0 : out;
    r.outputs[k] = y;
    error += std::fabs(kTarget[k] - y);
    r.solved = r.solved && (kTarget[k] > 0.5 ? (rules.half_is_one ? y >= 0.5 : y > 0.5) : y < 0.5);
  }
  r.fitness = (4.0 - error) * (4.0 - error);
  return r;
}

}  // namespace robozoo
