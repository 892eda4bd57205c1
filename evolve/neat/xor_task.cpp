#include "evolve/neat/xor_task.hpp"

#include <cmath>
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

XorResult evaluate_xor(const Genome& g, const GenomeLayout& layout) {
  const bool signed_output = layout.output_activation == Activation::SignedSigmoid;
  if (!signed_output && layout.output_activation != Activation::SteepenedSigmoid)
    throw std::invalid_argument("evaluate_xor: the output must be a signed or steepened sigmoid, not " +
                                activation_name(layout.output_activation));
  Network net(g, layout);
  static constexpr double kIn[4][2] = {{0, 0}, {0, 1}, {1, 0}, {1, 1}};
  static constexpr double kTarget[4] = {0, 1, 1, 0};
  XorResult r;
  double error = 0.0;
  r.solved = true;
  for (int k = 0; k < 4; ++k) {
    const double in[3] = {kIn[k][0], kIn[k][1], 1.0};
    double out = 0.0;
    net.query(in, &out);
    const double y = signed_output ? (out + 1.0) / 2.0 : out;
    r.outputs[k] = y;
    error += std::fabs(kTarget[k] - y);
    r.solved = r.solved && (kTarget[k] > 0.5 ? y > 0.5 : y < 0.5);
  }
  r.fitness = (4.0 - error) * (4.0 - error);
  return r;
}

}  // namespace robozoo
