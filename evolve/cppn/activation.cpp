#include "evolve/cppn/activation.hpp"

#include <stdexcept>

namespace robozoo {

std::string activation_name(Activation a) {
  switch (a) {
    case Activation::SignedSigmoid: return "signed_sigmoid";
    case Activation::SignedCosine: return "signed_cosine";
    case Activation::Gaussian: return "gaussian";
    case Activation::Linear: return "linear";
    case Activation::Sine: return "sine";
    case Activation::SteepenedSigmoid: return "steepened_sigmoid";
  }
  return "unknown";
}

Activation activation_from_name(const std::string& name) {
  for (int c = 0; c < kNumActivations; ++c) {
    const auto a = static_cast<Activation>(c);
    if (activation_name(a) == name) return a;
  }
  throw std::invalid_argument("unknown activation function '" + name + "'");
}

}  // namespace robozoo
