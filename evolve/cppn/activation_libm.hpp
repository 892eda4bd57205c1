#pragma once
// The CPPN activations computed with the C library's exp, cos and sin: the
// reference the tests compare robozoo's own functions (evolve/math/) with, and
// robozoo-bench's "before" baseline. Never used by an evolution, a replay or
// any other program's results (Network::use_libm_activations is for tests and
// benchmarks only): libm's bits depend on the build.
#include "evolve/cppn/activation.hpp"

namespace robozoo {

double activate_libm(Activation a, double x);
/// activate_libm(a, x[p]) for p in [0, n), written to y (y may equal x).
void activate_row_libm(Activation a, const double* x, double* y, int n);

}  // namespace robozoo
