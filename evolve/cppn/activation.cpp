#include "evolve/cppn/activation.hpp"

#include <stdexcept>

// On x86-64 the row loops are compiled twice, for the baseline (SSE2, two
// doubles a vector) and for AVX2 (four), and the loader picks the one the CPU
// runs. The bits are the same: the same IEEE operations element by element, no
// FMA (AVX2 does not include it, and contraction is off).
#if defined(__x86_64__) && defined(__has_attribute)
#if __has_attribute(target_clones)
#define ROBOZOO_ROW_CLONES __attribute__((target_clones("avx2", "default")))
#endif
#endif
#ifndef ROBOZOO_ROW_CLONES
#define ROBOZOO_ROW_CLONES
#endif

namespace robozoo {

ROBOZOO_ROW_CLONES void activate_row(Activation a, const double* x, double* y, int n) {
  switch (a) {
    case Activation::SignedSigmoid:
      for (int p = 0; p < n; ++p) y[p] = signed_sigmoid(x[p]);
      return;
    case Activation::SignedCosine:
      for (int p = 0; p < n; ++p) y[p] = math::cos(x[p]);
      return;
    case Activation::Gaussian:
      for (int p = 0; p < n; ++p) y[p] = gaussian(x[p]);
      return;
    case Activation::Linear:
      if (y != x)
        for (int p = 0; p < n; ++p) y[p] = x[p];
      return;
    case Activation::Sine:
      for (int p = 0; p < n; ++p) y[p] = math::sin(x[p]);
      return;
    case Activation::SteepenedSigmoid:
      for (int p = 0; p < n; ++p) y[p] = steepened_sigmoid(x[p]);
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
