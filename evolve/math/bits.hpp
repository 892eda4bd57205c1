#pragma once
// Exact access to the bits of a double, and the build guards of robozoo's own
// elementary functions (exp.hpp, trig.hpp, tanh.hpp).
//
// Those functions give the same bits from any conforming compiler at any
// optimisation level because they use only IEEE-754 double + - * / (each
// correctly rounded in the default round-to-nearest mode), comparisons and
// integer operations on the bit patterns. What would break that, and the guard:
// - fused multiply-add contraction (a*b+c rounded once): the project builds
//   with -ffp-contract=off, and every function body starts with
//   ROBOZOO_NO_FP_CONTRACT (clang's scoped pragma, which keeps clang's default
//   -ffp-contract=on from contracting here; gcc has no scoped form and relies on
//   the flag, as ISO C++ mode's default is off). -ffp-contract=fast overrides
//   both and changes the bits on machines with FMA: the pinned hashes of
//   tests/evolve/cppn/activation_test.cpp then fail;
// - -ffast-math (reassociation, reciprocal approximations): refused below;
// - x87 extended precision (32-bit x86 without SSE2): refused below.
#include <cstdint>
#include <cstring>

#if defined(__FAST_MATH__)
#error "robozoo's elementary functions need IEEE arithmetic: do not build with -ffast-math"
#endif
#if defined(__FLT_EVAL_METHOD__) && __FLT_EVAL_METHOD__ != 0
#error "robozoo's elementary functions need double arithmetic evaluated in double (FLT_EVAL_METHOD 0)"
#endif

#if defined(__clang__)
#define ROBOZOO_NO_FP_CONTRACT _Pragma("clang fp contract(off)")
#else
#define ROBOZOO_NO_FP_CONTRACT
#endif

namespace robozoo::math {

inline uint64_t bits_of(double x) {
  uint64_t u;
  std::memcpy(&u, &x, sizeof u);
  return u;
}

inline double from_bits(uint64_t u) {
  double x;
  std::memcpy(&x, &u, sizeof x);
  return x;
}

constexpr uint64_t kSignBit = 0x8000000000000000ULL;
/// The one NaN every function returns (positive quiet NaN): hardware differs in
/// the sign and payload of the NaN an invalid operation makes, so a NaN result
/// is replaced by this one and its bits are the same everywhere.
constexpr uint64_t kCanonicalNaNBits = 0x7ff8000000000000ULL;

// Selections are made with integer masks, not with floating-point comparisons:
// gcc (-ftrapping-math, the default) will not turn a comparison whose result
// feeds further arithmetic into a vector select, and leaves the loop scalar.

/// All ones when a > b, else zero; a and b below 2^63.
inline uint64_t mask_greater(uint64_t a, uint64_t b) { return 0 - ((b - a) >> 63); }
/// a where mask is all ones, b where it is zero.
inline double select(uint64_t mask, double a, double b) {
  return from_bits((bits_of(a) & mask) | (bits_of(b) & ~mask));
}
/// |x|'s bits.
inline uint64_t abs_bits(double x) { return bits_of(x) & ~kSignBit; }
/// All ones when x is a NaN.
inline uint64_t nan_mask(double x) { return mask_greater(abs_bits(x), 0x7ff0000000000000ULL); }
/// x, or the canonical NaN when x is a NaN (branch-free).
inline double canonical_nan(double x) { return select(nan_mask(x), from_bits(kCanonicalNaNBits), x); }

/// 0x1.8p52: adding it to |v| < 2^51 rounds v to the nearest integer (ties to
/// even) and leaves that integer in the low bits of the sum's bit pattern.
constexpr double kRoundShift = 0x1.8p52;

/// The integer k (two's complement) from k + kRoundShift, |k| < 2^51.
inline uint64_t int_from_shifted(double k_plus_shift) { return bits_of(k_plus_shift) - bits_of(kRoundShift); }

/// 2^k as a double for an integer-valued k in [-1022, 1023], from k + kRoundShift.
inline double pow2_from_shifted(double k_plus_shift) {
  return from_bits((int_from_shifted(k_plus_shift) + 1023) << 52);
}

}  // namespace robozoo::math
