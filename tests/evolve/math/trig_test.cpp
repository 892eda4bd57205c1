// robozoo's sin and cos against 80-bit long double (sinl, cosl): ulp bounds over
// random arguments, sweeps of the range CPPN sums reach, arguments next to
// multiples of pi/2 up to the reduction limit, and special values.
#include "evolve/math/trig.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>

#include "tests/support/ulp.hpp"

namespace robozoo::math {
namespace {

using namespace test;  // bits, Stream, ulp_error, kInf, kNaN
constexpr long double kPio2L = 1.570796326794896619231321691639751442L;

/// Both functions at x, the worse error; fails the test above `bound` ulp.
long double check(double x, long double bound) {
  const long double es = ulp_error(sin(x), sinl(static_cast<long double>(x)));
  const long double ec = ulp_error(cos(x), cosl(static_cast<long double>(x)));
  if (!(es <= bound)) ADD_FAILURE() << "sin(" << x << ") off by " << static_cast<double>(es) << " ulp";
  if (!(ec <= bound)) ADD_FAILURE() << "cos(" << x << ") off by " << static_cast<double>(ec) << " ulp";
  return std::max(es, ec);
}

TEST(Trig, WithinOneUlpWhereCppnSumsLie) {
  // CPPN sums of robozoo-bench's genomes lie in [-41, 51] (cosine's in [-12.5, 9.8]): dense sweeps of
  // [-60, 60] and [-pi, pi], random arguments in [-100, 100].
  long double worst = 0;
  for (int i = -600000; i <= 600000; ++i) {
    worst = std::max(worst, check(i * 1e-4, 1.0L));
    worst = std::max(worst, check(i * 5.3e-6, 1.0L));
  }
  Stream s(11);
  for (int i = 0; i < 1000000; ++i) worst = std::max(worst, check(s.uniform(-100.0, 100.0), 1.0L));
  EXPECT_LE(worst, 1.0L);
  EXPECT_GT(worst, 0.0L);
}

TEST(Trig, WithinOneUlpUpToTheReductionLimit) {
  Stream s(12);
  long double worst = 0;
  for (int i = 0; i < 1000000; ++i) worst = std::max(worst, check(s.uniform(-0x1p20, 0x1p20), 1.0L));
  // Log-uniform magnitudes from 2^-30 to 2^20, both signs.
  for (int i = 0; i < 500000; ++i) {
    const double x = std::ldexp(s.uniform(1.0, 2.0), static_cast<int>(s.next() % 50) - 30);
    worst = std::max(worst, check(i % 2 ? x : -x, 1.0L));
  }
  EXPECT_LE(worst, 1.0L);
}

TEST(Trig, NextToMultiplesOfHalfPi) {
  // The doubles nearest k pi/2 and their neighbours, where the reduction
  // cancels most: small k, random k, and the largest k below the limit.
  long double worst = 0;
  Stream s(13);
  auto around = [&](long long k) {
    double x = static_cast<double>(k * kPio2L);
    if (std::fabs(x) > 0x1p20) return;
    for (int j = 0; j < 3; ++j) x = std::nextafter(x, -kInf);
    for (int j = 0; j < 7; ++j, x = std::nextafter(x, kInf)) worst = std::max(worst, check(x, 1.0L));
  };
  for (long long k = -2000; k <= 2000; ++k) around(k);
  for (int i = 0; i < 100000; ++i) around(static_cast<long long>(s.next() % 667544) * (i % 2 ? 1 : -1));
  for (long long k = 667544 - 1000; k <= 667544; ++k) {
    around(k);
    around(-k);
  }
  EXPECT_LE(worst, 1.0L);
}

TEST(Trig, SpecialValues) {
  EXPECT_EQ(bits(sin(0.0)), bits(0.0));
  EXPECT_EQ(bits(sin(-0.0)), bits(-0.0));
  EXPECT_EQ(bits(cos(0.0)), bits(1.0));
  EXPECT_EQ(bits(cos(-0.0)), bits(1.0));
  const double tiny = std::numeric_limits<double>::denorm_min();
  EXPECT_EQ(bits(sin(tiny)), bits(tiny));
  EXPECT_EQ(bits(sin(-tiny)), bits(-tiny));
  EXPECT_EQ(bits(sin(DBL_MIN)), bits(DBL_MIN));
  EXPECT_EQ(bits(sin(1e-10)), bits(1e-10));
  EXPECT_EQ(cos(tiny), 1.0);
  EXPECT_EQ(cos(1e-10), 1.0);
  // The reduction limit: accurate at 2^20, the canonical NaN just beyond, at
  // +-inf and for NaN.
  EXPECT_LE(ulp_error(sin(0x1p20), sinl(0x1p20L)), 1.0L);
  EXPECT_LE(ulp_error(cos(-0x1p20), cosl(-0x1p20L)), 1.0L);
  for (double x :
       {std::nextafter(0x1p20, kInf), -std::nextafter(0x1p20, kInf), 1e7, 1e300, DBL_MAX, kInf, -kInf, kNaN, -kNaN}) {
    EXPECT_EQ(bits(sin(x)), kCanonicalNaNBits) << x;
    EXPECT_EQ(bits(cos(x)), kCanonicalNaNBits) << x;
  }
  // Exact symmetries that the reduction keeps.
  Stream s(14);
  for (int i = 0; i < 100000; ++i) {
    const double x = s.uniform(0.0, 1000.0);
    ASSERT_EQ(bits(sin(-x)), bits(-sin(x))) << x;
    ASSERT_EQ(bits(cos(-x)), bits(cos(x))) << x;
    ASSERT_LE(std::fabs(sin(x)), 1.0);
    ASSERT_LE(std::fabs(cos(x)), 1.0);
  }
}

}  // namespace
}  // namespace robozoo::math
