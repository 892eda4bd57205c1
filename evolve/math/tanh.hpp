#pragma once
// robozoo's tanh: the same bits from any compiler (evolve/math/bits.hpp), no
// libm, branch-free.
//
// With m = expm1(-2|x|) (exp.hpp's expm1, accurate near 0, so tanh is accurate
// near 0 too), tanh(|x|) = -m / (2 + m) for |x| < 1; for |x| >= 1, with
// m = expm1(2|x|), tanh(|x|) = 1 - 2 / (2 + m), where the rounding errors of the
// small quotient stay below the last bit. The sign of x is put back. tanh
// saturates: it is exactly +-1 from |x| = 19.1 on (m overflows to +inf for
// huge |x|, giving 1) and never exceeds it. Accuracy (tests/evolve/math/
// tanh_test.cpp, against 80-bit long double): within 2.5 ulp (2.2 seen, for
// |x| in 0.17-0.5, where expm1's own error of about 1.5 ulp passes through). tanh(+-0) = +-0,
// tanh(x) = x for subnormal x, tanh(+-inf) = +-1, NaN gives the canonical NaN.
#include "evolve/math/bits.hpp"
#include "evolve/math/exp.hpp"

namespace robozoo::math {

inline double tanh(double x) {
  ROBOZOO_NO_FP_CONTRACT
  const uint64_t sign = bits_of(x) & kSignBit;
  const double ax = from_bits(bits_of(x) ^ sign);
  // |x| < 1: tanh = -m / (2 + m), m = expm1(-2|x|) in (-0.87, 0].
  // |x| >= 1: tanh = 1 - 2 / (2 + m), m = expm1(2|x|) >= 6.38 (+inf for huge |x|).
  const uint64_t large = ~mask_greater(bits_of(1.0), bits_of(ax));  // ax >= 1 or NaN
  const double m = expm1(from_bits(bits_of(2.0 * ax) | (~large & kSignBit)));
  const double d = 2.0 + m;
  const double t = select(large, 1.0 - 2.0 / d, -m / d);
  return canonical_nan(from_bits(bits_of(t) | sign));
}

}  // namespace robozoo::math
