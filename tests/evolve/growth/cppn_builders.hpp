#pragma once
// Hand-built robot CPPNs for growth tests: genomes with no hidden node whose
// outputs are signed sigmoids of a few chosen links, so every output is known.
#include <cmath>

#include "evolve/cppn/genome.hpp"
#include "evolve/growth/growth.hpp"

namespace robozoo::testing {

inline double ssig(double x) { return 2.0 / (1.0 + std::exp(-x)) - 1.0; }
/// The input sum whose signed sigmoid is v, v in (-1, 1).
inline double inv_ssig(double v) { return std::log((1.0 + v) / (1.0 - v)); }

/// All 20 robot nodes, no links: every output is ssig(0) = 0.
inline Genome bare_robot_genome() {
  const GenomeLayout l = robot_layout();
  Genome g;
  g.id = 7;
  for (int i = 0; i < l.num_inputs; ++i)
    g.nodes.push_back({i, i == l.bias_input ? NodeKind::Bias : NodeKind::Input, Activation::Linear, 0.0});
  for (int o = 0; o < l.num_outputs; ++o)
    g.nodes.push_back({l.num_inputs + o, NodeKind::Output, l.output_activation, 1.0});
  return g;
}

/// Adds a link from input `in` (a CppnInput) to output `out` (a CppnOutput).
inline void link(Genome& g, int in, int out, double weight) {
  const int64_t innov = g.links.empty() ? 0 : g.links.back().innovation + 1;
  g.links.push_back({innov, in, robot_layout().num_inputs + out, weight, true, 0});
}

/// Output `out` becomes the constant ssig(inv_ssig(v)) ~ v (with bias input 1).
inline void constant(Genome& g, int out, double v) { link(g, kInBias, out, inv_ssig(v)); }

/// The growth defaults with a bias input of 1, the value constant() and the hand-worked
/// expectations of the growth tests assume (the default is the authors' 0.3).
inline GrowthParams unit_bias_growth() {
  GrowthParams p;
  p.bias_input = 1.0;
  return p;
}

}  // namespace robozoo::testing
