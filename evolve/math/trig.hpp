#pragma once
// robozoo's sin and cos: the same bits from any compiler (evolve/math/bits.hpp),
// no libm, branch-free so loops over them vectorise.
//
// Algorithm: x = k pi/2 + r with k = round(x 2/pi), |r| <= pi/4 (+ a hair), by
// Cody-Waite reduction with pi/2 in four parts: three of 33 significant bits
// (k * part exact for |k| < 2^20) and a 53-bit tail, the differences carried as
// a double-double r = hi + lo (error below 2^-130 absolute, so the reduction
// stays accurate even for arguments within 2^-60 of a multiple of pi/2). Then
// sin(r) and cos(r) by their Taylor series to r^17 and r^16 (truncation below
// 1e-19), and k mod 4 picks which one and its sign.
//
// Range: the reduction is exact for |x| <= 2^20 = 1048576 (far beyond what a
// CPPN sum reaches). Beyond it, and for +-inf, the result is the canonical NaN
// (bits.hpp); a NaN gives the canonical NaN.
// Accuracy (tests/evolve/math/trig_test.cpp, against 80-bit long double): within
// 1 ulp over |x| <= 2^20. sin(+-0) = +-0, sin(x) = x for |x| < 2^-26 (subnormals
// included), cos(+-0) = 1.
#include "evolve/math/bits.hpp"

namespace robozoo::math {

namespace trig_detail {

constexpr double kTwoOverPi = 0x1.45f306dc9c883p-1;
constexpr double kPio2_1 = 0x1.921fb54400000p+0;    // 33 significant bits
constexpr double kPio2_2 = 0x1.0b4611a600000p-34;   // 33
constexpr double kPio2_3 = 0x1.3198a2e000000p-69;   // 33
constexpr double kPio2_4 = 0x1.b839a252049c1p-104;  // the rest, rounded
/// Largest |x| the reduction handles exactly (|k| <= 667544 < 2^20).
constexpr double kMaxArgument = 0x1p20;

/// s + e = a + b exactly (Knuth's two-sum; any magnitudes).
inline void two_sum(double a, double b, double& s, double& e) {
  ROBOZOO_NO_FP_CONTRACT
  s = a + b;
  const double bb = s - a;
  e = (a - (s - bb)) + (b - bb);
}

struct Reduced {
  double shifted_k;  // k + kRoundShift; k mod 4 is in its low bits
  double hi, lo;     // r = hi + lo
};

inline Reduced reduce(double x) {
  ROBOZOO_NO_FP_CONTRACT
  const double shifted_k = x * kTwoOverPi + kRoundShift;
  const double k = shifted_k - kRoundShift;
  const double r1 = x - k * kPio2_1;  // exact
  double r2, e2, r3, e3;
  two_sum(r1, -(k * kPio2_2), r2, e2);
  two_sum(r2, -(k * kPio2_3), r3, e3);
  const double tail = (e2 + e3) - k * kPio2_4;
  double hi, lo;
  two_sum(r3, tail, hi, lo);
  return {shifted_k, hi, lo};
}

/// sin(hi + lo) for |hi| <= pi/4 + a hair, |lo| <= ulp(hi).
inline double sin_kernel(double hi, double lo) {
  ROBOZOO_NO_FP_CONTRACT
  const double z = hi * hi;
  const double s =
      -0x1.5555555555555p-3 +
      z * (0x1.1111111111111p-7 +
           z * (-0x1.a01a01a01a01ap-13 +
                z * (0x1.71de3a556c734p-19 +
                     z * (-0x1.ae64567f544e4p-26 +
                          z * (0x1.6124613a86d09p-33 + z * (-0x1.ae7f3e733b81fp-41 + z * 0x1.952c77030ad4ap-49))))));
  // sin(hi + lo) = sin(hi) + lo cos(hi), cos(hi) ~ 1 - z/2.
  return hi + ((z * hi) * s + lo * (1.0 - 0.5 * z));
}

/// cos(hi + lo) for |hi| <= pi/4 + a hair, |lo| <= ulp(hi).
inline double cos_kernel(double hi, double lo) {
  ROBOZOO_NO_FP_CONTRACT
  const double z = hi * hi;
  const double c =
      0x1.5555555555555p-5 +
      z * (-0x1.6c16c16c16c17p-10 +
           z * (0x1.a01a01a01a01ap-16 +
                z * (-0x1.27e4fb7789f5cp-22 +
                     z * (0x1.1eed8eff8d898p-29 + z * (-0x1.93974a8c07c9dp-37 + z * 0x1.ae7f3e733b81fp-45)))));
  // 1 - z/2 + z^2 c - lo sin(hi), with the rounding error of w = 1 - z/2 added back.
  const double hz = 0.5 * z;
  const double w = 1.0 - hz;
  return w + (((1.0 - w) - hz) + ((z * z) * c - hi * lo));
}

/// sin(x) (quadrant_offset 0) or cos(x) (quadrant_offset 1): cos(x) = sin(x + pi/2).
inline double sin_or_cos(double x, uint64_t quadrant_offset) {
  ROBOZOO_NO_FP_CONTRACT
  // |x| > kMaxArgument, +-inf and NaN: reduce a NaN.
  const double xr = select(mask_greater(abs_bits(x), bits_of(kMaxArgument)), from_bits(kCanonicalNaNBits), x);
  const Reduced red = reduce(xr);
  const double s = sin_kernel(red.hi, red.lo);
  const double c = cos_kernel(red.hi, red.lo);
  // Quadrant q = (k + offset) mod 4: sin, cos, -sin, -cos.
  const uint64_t q = bits_of(red.shifted_k) + quadrant_offset;
  const uint64_t use_cos = 0 - (q & 1);  // all ones or zero
  const uint64_t chosen = (bits_of(c) & use_cos) | (bits_of(s) & ~use_cos);
  return canonical_nan(from_bits(chosen ^ ((q & 2) << 62)));
}

}  // namespace trig_detail

/// sin(x), within 1 ulp for |x| <= 2^20; NaN beyond.
inline double sin(double x) {
  ROBOZOO_NO_FP_CONTRACT
  const double y = trig_detail::sin_or_cos(x, 0);
  // |x| < 2^-26: sin x = x (1 - x^2/6 + ...) rounds to x (and -0 stays -0).
  return select(mask_greater(bits_of(0x1p-26), abs_bits(x)), x, y);
}

/// cos(x), within 1 ulp for |x| <= 2^20; NaN beyond.
inline double cos(double x) { return trig_detail::sin_or_cos(x, 1); }

}  // namespace robozoo::math
