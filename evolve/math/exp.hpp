#pragma once
// robozoo's exp and expm1: the same bits from any compiler (evolve/math/bits.hpp),
// no libm, branch-free so loops over them vectorise.
//
// Algorithm: x = k ln2 + r with k = round(x / ln2) and |r| <= ln2/2 (+ a hair),
// by Cody-Waite reduction with ln2 in two parts (the first has 42 significant
// bits, so k * part1 and x - k * part1 are exact for |k| < 2^11); e^r - 1 by
// its Taylor series to r^13 (truncation below 5e-18 relative), evaluated as
// r + r^2 P(r); then the result is scaled by 2^k in two exact steps, so a
// subnormal result is rounded once.
//
// Accuracy (tests/evolve/math/exp_test.cpp, against 80-bit long double): exp
// within 1 ulp where the result is normal (subnormal results within 1 ulp of
// the smallest subnormal); expm1 within 2 ulp.
// Special values: exp(+-0) = 1; exp(x) = +inf for x > 709.782712893384 (overflow),
// +0 below -745.1332191019412 (underflow, subnormal results in between),
// exp(+inf) = +inf, exp(-inf) = +0. expm1(x) = -1 for x < -38 (rounded), +inf on
// overflow, expm1(+-0) = +-0. NaN gives the canonical NaN (bits.hpp).
#include "evolve/math/bits.hpp"

namespace robozoo::math {

namespace exp_detail {

constexpr double kInvLn2 = 0x1.71547652b82fep+0;
constexpr double kLn2Hi = 0x1.62e42fefa3800p-1;   // 42 significant bits
constexpr double kLn2Lo = 0x1.ef35793c76730p-45;  // ln2 - kLn2Hi, rounded
// Arguments are clamped to this range before reduction (|k| <= 1443, so both
// halves of 2^k are normal numbers); outside it exp has long overflowed or
// underflowed and expm1 is -1.
constexpr double kClamp = 1000.0;

/// e^r - 1 for |r| <= 0.35: r + r^2 (1/2! + r/3! + ... + r^11/13!).
inline double expm1_kernel(double r) {
  ROBOZOO_NO_FP_CONTRACT
  const double p =
      0x1.0000000000000p-1 +
      r * (0x1.5555555555555p-3 +
           r * (0x1.5555555555555p-5 +
                r * (0x1.1111111111111p-7 +
                     r * (0x1.6c16c16c16c17p-10 +
                          r * (0x1.a01a01a01a01ap-13 +
                               r * (0x1.a01a01a01a01ap-16 +
                                    r * (0x1.71de3a556c734p-19 +
                                         r * (0x1.27e4fb7789f5cp-22 +
                                              r * (0x1.ae64567f544e4p-26 +
                                                   r * (0x1.1eed8eff8d898p-29 + r * 0x1.6124613a86d09p-33))))))))));
  return r + (r * r) * p;
}

/// The reduction: k (integer-valued, plus kRoundShift) and r = x - k ln2.
struct Reduced {
  double shifted_k;  // k + kRoundShift
  double k;
  double r;
};

inline Reduced reduce(double x) {
  ROBOZOO_NO_FP_CONTRACT
  // |x| > kClamp (+-inf included, a NaN excluded): +-kClamp.
  const uint64_t big = mask_greater(abs_bits(x), bits_of(kClamp)) & ~nan_mask(x);
  const double xc = select(big, from_bits((bits_of(x) & kSignBit) | bits_of(kClamp)), x);
  const double shifted_k = xc * kInvLn2 + kRoundShift;
  const double k = shifted_k - kRoundShift;
  const double r = (xc - k * kLn2Hi) - k * kLn2Lo;
  return {shifted_k, k, r};
}

/// 2^k as two factors 2^k1 * 2^k2 (k1 = round(k/2), k2 = k - k1), each normal.
struct Scale {
  double s1, s2;
};

inline Scale split_pow2(double k) {
  ROBOZOO_NO_FP_CONTRACT
  const double shifted_k1 = k * 0.5 + kRoundShift;
  const double k1 = shifted_k1 - kRoundShift;
  return {pow2_from_shifted(shifted_k1), pow2_from_shifted((k - k1) + kRoundShift)};
}

}  // namespace exp_detail

/// e^x.
inline double exp(double x) {
  ROBOZOO_NO_FP_CONTRACT
  using namespace exp_detail;
  const Reduced red = reduce(x);
  const double e = 1.0 + expm1_kernel(red.r);
  const Scale sc = split_pow2(red.k);
  return canonical_nan((e * sc.s1) * sc.s2);
}

/// e^x - 1, accurate near 0 (where exp(x) - 1 would cancel).
inline double expm1(double x) {
  ROBOZOO_NO_FP_CONTRACT
  using namespace exp_detail;
  const Reduced red = reduce(x);
  const double p = expm1_kernel(red.r);
  const Scale sc = split_pow2(red.k);
  // -1 <= k <= 53: 2^k - 1 is exact, so 2^k p + (2^k - 1) rounds twice at most.
  const double pow2k = sc.s1 * sc.s2;
  const double near = (p * sc.s1) * sc.s2 + (pow2k - 1.0);
  // Otherwise 2^k (1 + p) - 1: the error of 1 + p is scaled down (k < -1) or the
  // -1 is far below the result's last bit (k > 53).
  const double far = ((1.0 + p) * sc.s1) * sc.s2 - 1.0;
  const uint64_t k = int_from_shifted(red.shifted_k);
  const uint64_t use_near = ((((k + 1) | (53 - k)) >> 63) - 1);  // all ones for -1 <= k <= 53
  const double y = select(use_near, near, far);
  // +-0 keeps its sign (the sums above would turn -0 into +0).
  const uint64_t zero = 0 - ((abs_bits(x) - 1) >> 63);
  return canonical_nan(select(zero, x, y));
}

}  // namespace robozoo::math
