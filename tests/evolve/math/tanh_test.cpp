// robozoo's tanh against 80-bit long double (tanhl): ulp bound over random
// arguments, the CTRNN's range and near 0, saturation, and special values.
#include "evolve/math/tanh.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>

#include "tests/support/ulp.hpp"

namespace robozoo::math {
namespace {

using namespace test;  // bits, Stream, ulp_error, kInf, kNaN

long double check(double x, long double bound) {
  const long double e = ulp_error(tanh(x), tanhl(static_cast<long double>(x)));
  if (!(e <= bound)) ADD_FAILURE() << "tanh(" << x << ") off by " << static_cast<double>(e) << " ulp";
  return e;
}

TEST(Tanh, WithinTwoAndAHalfUlp) {
  long double worst = 0;
  // The CTRNN's arguments (y + omega) of robozoo-bench's robots lie in
  // [-126, 216], saturated (exactly +-1, SaturatesAtOne) beyond +-19.1: dense
  // sweep of [-40, 40], random arguments, and magnitudes from 2^-1074 to 64.
  for (int i = -800000; i <= 800000; ++i) worst = std::max(worst, check(i * 5e-5, 2.5L));
  Stream s(21);
  for (int i = 0; i < 1000000; ++i) worst = std::max(worst, check(s.uniform(-25.0, 25.0), 2.5L));
  for (int i = 0; i < 500000; ++i) {
    const double x = std::ldexp(s.uniform(1.0, 2.0), static_cast<int>(s.next() % 1080) - 1074);
    worst = std::max(worst, check(i % 2 ? x : -x, 2.5L));
  }
  EXPECT_LE(worst, 2.5L);
  EXPECT_GT(worst, 0.0L);
}

TEST(Tanh, SaturatesAtOne) {
  // Never beyond +-1, exactly +-1 from |x| = 19.1 on, monotone on a sweep.
  double prev = -1.0;
  for (double x = -30.0; x <= 30.0; x += 1e-4) {
    const double t = tanh(x);
    ASSERT_LE(std::fabs(t), 1.0) << x;
    ASSERT_GE(t, prev) << x;
    prev = t;
    if (std::fabs(x) >= 19.1) {
      ASSERT_EQ(std::fabs(t), 1.0) << x;
    }
  }
  EXPECT_EQ(tanh(20.0), 1.0);
  EXPECT_EQ(tanh(-20.0), -1.0);
  EXPECT_EQ(tanh(1e300), 1.0);
  EXPECT_EQ(tanh(DBL_MAX), 1.0);
  EXPECT_EQ(tanh(-DBL_MAX), -1.0);
}

TEST(Tanh, SpecialValues) {
  EXPECT_EQ(bits(tanh(0.0)), bits(0.0));
  EXPECT_EQ(bits(tanh(-0.0)), bits(-0.0));
  const double tiny = std::numeric_limits<double>::denorm_min();
  EXPECT_EQ(bits(tanh(tiny)), bits(tiny));
  EXPECT_EQ(bits(tanh(-tiny)), bits(-tiny));
  EXPECT_EQ(bits(tanh(DBL_MIN)), bits(DBL_MIN));
  EXPECT_EQ(tanh(1e-20), 1e-20);
  EXPECT_EQ(tanh(kInf), 1.0);
  EXPECT_EQ(tanh(-kInf), -1.0);
  EXPECT_EQ(bits(tanh(kNaN)), kCanonicalNaNBits);
  EXPECT_EQ(bits(tanh(-kNaN)), kCanonicalNaNBits);
  Stream s(22);
  for (int i = 0; i < 100000; ++i) {
    const double x = s.uniform(0.0, 30.0);
    ASSERT_EQ(bits(tanh(-x)), bits(-tanh(x))) << x;
  }
}

}  // namespace
}  // namespace robozoo::math
