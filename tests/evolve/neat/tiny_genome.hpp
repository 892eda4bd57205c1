#pragma once
// The smallest genome the NEAT tests build parents from: inputs 0 and 1, the bias 2
// and output 3 (drawing positions 0 and 1), no links. Tests add hidden nodes and links.
#include <cstdint>

#include "evolve/cppn/genome.hpp"

namespace robozoo::test {

inline Genome tiny_genome(int64_t id, Activation output = Activation::SignedSigmoid) {
  Genome g;
  g.id = id;
  g.nodes = {{0, NodeKind::Input, Activation::Linear, 0.0},
             {1, NodeKind::Input, Activation::Linear, 0.0},
             {2, NodeKind::Bias, Activation::Linear, 0.0},
             {3, NodeKind::Output, output, 1.0}};
  return g;
}

/// The layout of tiny_genome (XOR-sized): inputs 0 and 1, the bias 2, `outputs`
/// outputs from 3, hidden nodes after them.
inline GenomeLayout tiny_layout(int outputs = 1) {
  GenomeLayout l;
  l.num_inputs = 3;
  l.bias_input = 2;
  l.num_outputs = outputs;
  return l;
}

}  // namespace robozoo::test
