#include "evolve/cppn/activation_libm.hpp"

#include <cmath>

namespace robozoo {

double activate_libm(Activation a, double x) {
  switch (a) {
    case Activation::SignedSigmoid: return 2.0 / (1.0 + std::exp(-x)) - 1.0;
    case Activation::SignedCosine: return std::cos(x);
    case Activation::Gaussian: return std::exp(-x * x);
    case Activation::Linear: return x;
    case Activation::Sine: return std::sin(x);
    case Activation::SteepenedSigmoid: return 1.0 / (1.0 + std::exp(-4.9 * x));
  }
  return 0.0;
}

void activate_row_libm(Activation a, const double* x, double* y, int n) {
  switch (a) {
    case Activation::SignedSigmoid:
      for (int p = 0; p < n; ++p) y[p] = std::exp(-x[p]);
      for (int p = 0; p < n; ++p) y[p] = 2.0 / (1.0 + y[p]) - 1.0;
      return;
    case Activation::SignedCosine:
      for (int p = 0; p < n; ++p) y[p] = std::cos(x[p]);
      return;
    case Activation::Gaussian:
      for (int p = 0; p < n; ++p) y[p] = std::exp(-x[p] * x[p]);
      return;
    default:
      for (int p = 0; p < n; ++p) y[p] = activate_libm(a, x[p]);
      return;
  }
}

}  // namespace robozoo
