#pragma once
// Test helpers for robozoo's elementary functions: the error of a double result
// in units in the last place of the exact value (80-bit long double reference,
// x86-64), and a deterministic stream of arguments.
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "evolve/math/bits.hpp"

namespace robozoo::math::test {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// |y - ref| in ulps of ref (the spacing of doubles at ref; 2^-1074 for
/// results in the subnormal range). Infinite if one is NaN or infinite and the
/// other is not the same.
inline long double ulp_error(double y, long double ref) {
  if (std::isnan(y) || std::isnan(ref)) return std::isnan(y) && std::isnan(ref) ? 0.0L : INFINITY;
  if (std::isinf(ref) || std::isinf(y)) return static_cast<long double>(y) == ref ? 0.0L : INFINITY;
  const long double a = fabsl(ref);
  int e = a == 0.0L ? -1074 : ilogbl(a) - 52;
  if (e < -1074) e = -1074;
  return fabsl(static_cast<long double>(y) - ref) / ldexpl(1.0L, e);
}

inline uint64_t bits(double x) {
  uint64_t u;
  std::memcpy(&u, &x, sizeof u);
  return u;
}

/// splitmix64: a fixed, seedable stream (the same arguments on every run).
struct Stream {
  uint64_t s;
  explicit Stream(uint64_t seed) : s(seed) {}
  uint64_t next() {
    uint64_t z = (s += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  /// Uniform in [lo, hi).
  /// Uniform in [lo, hi) (never contracted: the pinned hashes depend on these bits).
  double uniform(double lo, double hi) {
    ROBOZOO_NO_FP_CONTRACT
    return lo + (hi - lo) * (static_cast<double>(next() >> 11) * 0x1p-53);
  }
};

/// FNV-1a over the bits of a sequence of doubles.
struct BitsHash {
  uint64_t h = 0xcbf29ce484222325ULL;
  void add(double x) {
    uint64_t u = bits(x);
    for (int i = 0; i < 8; ++i) {
      h ^= (u >> (8 * i)) & 0xff;
      h *= 0x100000001b3ULL;
    }
  }
};

}  // namespace robozoo::math::test
