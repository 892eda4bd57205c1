#pragma once
// XOR, the NEAT paper's benchmark, as a check of the NEAT core.
//
// Layout: 3 inputs (x1, x2 in {0, 1}; bias 1.0 at input index 2, kind Bias),
// 1 output: a signed sigmoid mapped to (out + 1) / 2 in (0, 1), i.e. the
// logistic function of the output's net input (the project's preset), or the
// NEAT paper's steepened sigmoid 1 / (1 + e^(-4.9 x)), read as it is. Fitness (4 - sum |error|)^2 as
// in the NEAT paper (0..16). Solved when every pattern's mapped output is on
// the right side of 0.5 (> 0.5 for 1, < 0.5 for 0). The CPPN is queried as
// every CPPN of the project is (Network, 10 synchronous updates, values reset
// before each pattern).
#include <array>

#include "evolve/cppn/genome.hpp"

namespace robozoo {

struct XorResult {
  double fitness = 0.0;             ///< (4 - sum |error|)^2 (fitness units, 0..16)
  bool solved = false;              ///< every pattern on the right side of 0.5
  std::array<double, 4> outputs{};  ///< mapped outputs for (0,0), (0,1), (1,0), (1,1)
};

/// How a network is read on XOR. The defaults are the project's CPPN query above;
/// the NEAT paper's preset uses Stanley's own evaluation (his NEAT C++:
/// Network::activate and experiments.cpp's xor_evaluate).
struct XorRules {
  /// Stanley's activation: a node outputs 0 until some input reaches it through enabled links
  /// (his nodes stay inactive until an active node feeds them), and an acyclic network is
  /// relaxed to its steady state (he activates depth + 2 times; here as many updates as nodes).
  /// An output no input reaches makes the network "flawed": fitness 0.001, outputs 0, not solved.
  bool stanley_activation = false;
  /// Stanley's winner test: an output of exactly 0.5 counts as a 1 (out >= 0.5); false: > 0.5.
  bool half_is_one = false;
};

/// The XOR layout: inputs x1, x2, bias (index 2); one output with `output`
/// (SignedSigmoid or SteepenedSigmoid).
GenomeLayout xor_layout(Activation output = Activation::SignedSigmoid);

/// Evaluates g on the four patterns. Throws std::invalid_argument if g does
/// not fit `layout`, or if the layout's output is neither sigmoid.
XorResult evaluate_xor(const Genome& g, const GenomeLayout& layout = xor_layout(), const XorRules& rules = {});

}  // namespace robozoo
