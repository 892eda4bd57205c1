#pragma once
// CPPN activation functions, with HyperNEAT's definitions (docs/method.md, "The CPPN"),
// plus the NEAT paper's steepened sigmoid for its XOR check. exp, cos and sin are
// robozoo's own (evolve/math/): the same bits from any compiler, no libm.
#include <cstdint>
#include <string>

#include "evolve/math/exp.hpp"
#include "evolve/math/trig.hpp"

namespace robozoo {

/// Activation codes are part of the log format: never renumber.
enum class Activation : int8_t {
  SignedSigmoid = 0,     ///< 2 / (1 + e^-x) - 1, in (-1, 1)
  SignedCosine = 1,      ///< cos(x)
  Gaussian = 2,          ///< exp(-x^2)
  Linear = 3,            ///< x (off by default; available for experiments and tests)
  Sine = 4,              ///< sin(x) (off by default)
  SteepenedSigmoid = 5,  ///< 1 / (1 + e^(-4.9 x)), in (0, 1): the NEAT paper's (robozoo-xor --preset neat-paper)
};
constexpr int kNumActivations = 6;

/// One definition per activation, shared by the scalar and the row path, so
/// they give the same bits.
inline double signed_sigmoid(double x) { return 2.0 / (1.0 + math::exp(-x)) - 1.0; }
inline double gaussian(double x) { return math::exp(-x * x); }
inline double steepened_sigmoid(double x) { return 1.0 / (1.0 + math::exp(-4.9 * x)); }

inline double activate(Activation a, double x) {
  switch (a) {
    case Activation::SignedSigmoid: return signed_sigmoid(x);
    case Activation::SignedCosine: return math::cos(x);
    case Activation::Gaussian: return gaussian(x);
    case Activation::Linear: return x;
    case Activation::Sine: return math::sin(x);
    case Activation::SteepenedSigmoid: return steepened_sigmoid(x);
  }
  return 0.0;
}

/// activate(a, x[p]) for p in [0, n), written to y (y may equal x). Every element
/// gets exactly activate()'s operations (element-wise, branch-free, no
/// -ffast-math), so the bits are the same; the loops are shaped for the
/// compiler to vectorise.
void activate_row(Activation a, const double* x, double* y, int n);

/// Short lower-case name ("signed_sigmoid", "signed_cosine", "gaussian", "linear", "sine",
/// "steepened_sigmoid").
std::string activation_name(Activation a);
/// Inverse of activation_name; throws std::invalid_argument for an unknown name.
Activation activation_from_name(const std::string& name);
/// True for codes 0..kNumActivations-1.
inline bool valid_activation(int code) { return code >= 0 && code < kNumActivations; }

}  // namespace robozoo
