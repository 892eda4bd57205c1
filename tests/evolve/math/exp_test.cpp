// robozoo's exp and expm1 against 80-bit long double (expl, expm1l): ulp bounds
// over random arguments, sweeps of the range CPPN sums reach, and special values.
#include "evolve/math/exp.hpp"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <limits>

#include "tests/support/ulp.hpp"

namespace robozoo::math {
namespace {

using namespace test;  // bits, Stream, ulp_error, kInf, kNaN

/// Largest ulp error of exp over `count` arguments drawn by `draw`; results in
/// the subnormal range are checked separately (their ulp is 2^-1074).
template <class Draw>
long double max_exp_error(int count, Draw draw) {
  long double worst = 0;
  for (int i = 0; i < count; ++i) {
    const double x = draw();
    const long double e = ulp_error(exp(x), expl(static_cast<long double>(x)));
    if (e > worst) worst = e;
    if (!(e <= 1.0L)) ADD_FAILURE() << "exp(" << x << ") off by " << static_cast<double>(e) << " ulp";
  }
  return worst;
}

TEST(Exp, WithinOneUlpOverTheWholeFiniteRange) {
  Stream s(1);
  // Every result from the smallest subnormal to the largest double.
  const long double worst = max_exp_error(2000000, [&] { return s.uniform(-745.2, 709.78); });
  EXPECT_LE(worst, 1.0L);
  EXPECT_GT(worst, 0.0L);  // the comparison measures something
}

TEST(Exp, WithinOneUlpWhereCppnSumsLie) {
  // Signed sigmoid e^-x, Gaussian e^(-x^2), steepened sigmoid e^(-4.9x): CPPN
  // sums of robozoo-bench's genomes lie in [-41, 51] (Gaussian arguments in [-12.5, 15.3]); dense sweep of [-60, 60]
  // and of [-1, 1], and random squares for the Gaussian.
  long double worst = 0;
  for (int i = -600000; i <= 600000; ++i) {
    const double x = i * 1e-4;
    worst = std::max(worst, ulp_error(exp(x), expl(static_cast<long double>(x))));
    const double y = i * 1e-6;
    worst = std::max(worst, ulp_error(exp(y), expl(static_cast<long double>(y))));
  }
  Stream s(2);
  worst = std::max(worst, max_exp_error(1000000, [&] {
                     const double v = s.uniform(-30.0, 30.0);
                     return -v * v;
                   }));
  EXPECT_LE(worst, 1.0L);
}

TEST(Exp, SpecialValues) {
  EXPECT_EQ(bits(exp(0.0)), bits(1.0));
  EXPECT_EQ(bits(exp(-0.0)), bits(1.0));
  EXPECT_EQ(exp(kInf), kInf);
  EXPECT_EQ(bits(exp(-kInf)), bits(0.0));
  EXPECT_EQ(bits(exp(kNaN)), kCanonicalNaNBits);
  EXPECT_EQ(bits(exp(-kNaN)), kCanonicalNaNBits);
  auto err = [](double x) { return ulp_error(exp(x), expl(static_cast<long double>(x))); };
  EXPECT_LE(err(1.0), 1.0L);
  // Overflow threshold: ln(DBL_MAX) = 709.782712893384, just below and above.
  EXPECT_LE(err(709.78), 1.0L);
  EXPECT_LE(err(709.782712893383), 1.0L);
  EXPECT_EQ(exp(709.782712893385), kInf);
  EXPECT_EQ(exp(710.0), kInf);
  EXPECT_EQ(exp(1e300), kInf);
  EXPECT_EQ(exp(DBL_MAX), kInf);
  // Underflow: subnormal results, within 1 ulp of the smallest subnormal, and 0
  // below ln(2^-1075) = -745.1332191019412.
  EXPECT_LE(err(-708.3964185322641), 1.0L);  // near DBL_MIN
  for (double x = -708.5; x > -745.2; x -= 0.0137) {
    const long double e = ulp_error(exp(x), expl(static_cast<long double>(x)));
    EXPECT_LE(e, 1.0L) << x;
  }
  EXPECT_EQ(bits(exp(-745.14)), bits(0.0));
  EXPECT_EQ(bits(exp(-1000.0)), bits(0.0));
  EXPECT_EQ(bits(exp(-DBL_MAX)), bits(0.0));
  // Subnormal and tiny arguments: exp = 1 (correctly rounded).
  EXPECT_EQ(exp(std::numeric_limits<double>::denorm_min()), 1.0);
  EXPECT_EQ(exp(-std::numeric_limits<double>::denorm_min()), 1.0);
  EXPECT_EQ(exp(1e-300), 1.0);
}

TEST(Expm1, WithinTwoUlp) {
  Stream s(3);
  long double worst = 0;
  for (int i = 0; i < 1000000; ++i) {
    double x = s.uniform(-45.0, 45.0);
    if (i % 2) x = x * 1e-3;
    if (i % 4 == 1) x = x * 1e-9;
    const long double e = ulp_error(expm1(x), expm1l(static_cast<long double>(x)));
    worst = std::max(worst, e);
    if (!(e <= 2.0L)) ADD_FAILURE() << "expm1(" << x << ") off by " << static_cast<double>(e) << " ulp";
  }
  for (int i = -400000; i <= 400000; ++i) {
    const double x = i * 1e-5;
    worst = std::max(worst, ulp_error(expm1(x), expm1l(static_cast<long double>(x))));
  }
  EXPECT_LE(worst, 2.0L);
  for (double x = 1.0; x < 709.78; x *= 1.37)
    EXPECT_LE(ulp_error(expm1(x), expm1l(static_cast<long double>(x))), 2.0L) << x;
}

TEST(Expm1, SpecialValues) {
  EXPECT_EQ(bits(expm1(0.0)), bits(0.0));
  EXPECT_EQ(bits(expm1(-0.0)), bits(-0.0));
  const double tiny = std::numeric_limits<double>::denorm_min();
  EXPECT_EQ(bits(expm1(tiny)), bits(tiny));
  EXPECT_EQ(bits(expm1(-tiny)), bits(-tiny));
  EXPECT_EQ(expm1(1e-300), 1e-300);
  EXPECT_EQ(expm1(-40.0), -1.0);
  EXPECT_EQ(expm1(-kInf), -1.0);
  EXPECT_EQ(expm1(-DBL_MAX), -1.0);
  EXPECT_EQ(expm1(kInf), kInf);
  EXPECT_EQ(expm1(710.0), kInf);
  EXPECT_LE(ulp_error(expm1(709.78), expm1l(static_cast<long double>(709.78))), 2.0L);
  EXPECT_EQ(bits(expm1(kNaN)), kCanonicalNaNBits);
}

}  // namespace
}  // namespace robozoo::math
