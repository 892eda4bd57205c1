#include "evolve/cppn/activation.hpp"

#include <stdexcept>

namespace robozoo {

void activate_row(Activation a, const double* x, double* y, int n) {
  switch (a) {
    case Activation::SignedSigmoid:
      for (int p = 0; p < n; ++p) y[p] = std::exp(-x[p]);
      for (int p = 0; p < n; ++p) y[p] = signed_sigmoid_from_exp(y[p]);
      return;
    case Activation::SignedCosine:
      for (int p = 0; p < n; ++p) y[p] = std::cos(x[p]);
      return;
    case Activation::Gaussian:
      for (int p = 0; p < n; ++p) y[p] = std::exp(-x[p] * x[p]);
      return;
    case Activation::Linear:
      if (y != x)
        for (int p = 0; p < n; ++p) y[p] = x[p];
      return;
    case Activation::Sine:
      for (int p = 0; p < n; ++p) y[p] = std::sin(x[p]);
      return;
    case Activation::SteepenedSigmoid:
      for (int p = 0; p < n; ++p) y[p] = activate(Activation::SteepenedSigmoid, x[p]);
      return;
  }
  for (int p = 0; p < n; ++p) y[p] = 0.0;
}

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
