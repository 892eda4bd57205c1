#pragma once
// CPPN activation functions, with HyperNEAT's definitions (DESIGN.md section 2).
#include <cmath>
#include <cstdint>
#include <string>

namespace robozoo {

/// Activation codes are part of the log format: never renumber.
enum class Activation : int8_t {
  SignedSigmoid = 0,  ///< 2 / (1 + e^-x) - 1, in (-1, 1)
  SignedCosine = 1,   ///< cos(x)
  Gaussian = 2,       ///< exp(-x^2)
  Linear = 3,         ///< x (off by default; available for experiments and tests)
  Sine = 4,           ///< sin(x) (off by default)
};
constexpr int kNumActivations = 5;

inline double activate(Activation a, double x) {
  switch (a) {
    case Activation::SignedSigmoid: return 2.0 / (1.0 + std::exp(-x)) - 1.0;
    case Activation::SignedCosine: return std::cos(x);
    case Activation::Gaussian: return std::exp(-x * x);
    case Activation::Linear: return x;
    case Activation::Sine: return std::sin(x);
  }
  return 0.0;
}

/// Short lower-case name ("signed_sigmoid", "signed_cosine", "gaussian", "linear", "sine").
std::string activation_name(Activation a);
/// Inverse of activation_name; throws std::invalid_argument for an unknown name.
Activation activation_from_name(const std::string& name);
/// True for codes 0..kNumActivations-1.
inline bool valid_activation(int code) { return code >= 0 && code < kNumActivations; }

}  // namespace robozoo
