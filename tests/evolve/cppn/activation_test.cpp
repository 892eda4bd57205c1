// The CPPN activations: the row path (vectorised loops) gives the scalar path's
// bits, the functions agree with the C library's to rounding, and the bits of a
// fixed set of arguments are pinned, so a build (compiler, optimisation level,
// machine) that computes any other bits fails here.
#include "evolve/cppn/activation.hpp"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <limits>
#include <vector>

#include "evolve/cppn/activation_libm.hpp"
#include "evolve/math/tanh.hpp"
#include "tests/support/ulp.hpp"

namespace robozoo {
namespace {

using math::test::bits;
using math::test::BitsHash;
using math::test::Stream;

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// Arguments: random sums in [-60, 60] and [-3, 3], special values, and
/// arguments at the edges of each function's range.
std::vector<double> arguments(uint64_t seed, int random_count) {
  std::vector<double> x = {0.0,
                           -0.0,
                           std::numeric_limits<double>::denorm_min(),
                           -DBL_MIN,
                           1e-300,
                           1.0,
                           -1.0,
                           0.5,
                           710.0,
                           -710.0,
                           745.2,
                           -745.2,
                           1e10,
                           -1e10,
                           0x1p20,
                           -0x1p20,
                           1.5707963267948966,
                           3.141592653589793,
                           27.0,
                           -27.0,
                           kInf,
                           -kInf,
                           kNaN,
                           DBL_MAX};
  Stream s(seed);
  for (int i = 0; i < random_count; ++i) x.push_back(i % 2 ? s.uniform(-60.0, 60.0) : s.uniform(-3.0, 3.0));
  return x;
}

TEST(Activation, RowGivesTheScalarBits) {
  const std::vector<double> x = arguments(1, 5000);
  for (int c = 0; c < kNumActivations; ++c) {
    const auto a = static_cast<Activation>(c);
    for (int n : {1, 2, 3, 7, 64, static_cast<int>(x.size())}) {
      for (int offset : {0, 1, 5}) {
        if (offset + n > static_cast<int>(x.size())) continue;
        std::vector<double> out(n), in_place(x.begin() + offset, x.begin() + offset + n);
        activate_row(a, x.data() + offset, out.data(), n);
        activate_row(a, in_place.data(), in_place.data(), n);
        for (int p = 0; p < n; ++p) {
          const uint64_t want = bits(activate(a, x[offset + p]));
          ASSERT_EQ(bits(out[p]), want) << activation_name(a) << " at " << x[offset + p];
          ASSERT_EQ(bits(in_place[p]), want) << activation_name(a) << " at " << x[offset + p];
        }
      }
    }
  }
}

TEST(Activation, AgreesWithTheCLibraryToRounding) {
  // The same functions: within a few ulp of 1 (all outputs lie in [-1, 1]).
  const std::vector<double> x = arguments(2, 200000);
  for (int c = 0; c < kNumActivations; ++c) {
    const auto a = static_cast<Activation>(c);
    for (double v : x) {
      if (std::isnan(v) || std::isinf(v) || std::fabs(v) > 0x1p20) continue;
      const double got = activate(a, v), ref = activate_libm(a, v);
      if (a == Activation::Linear) {
        ASSERT_EQ(bits(got), bits(ref));
        continue;
      }
      ASSERT_LE(std::fabs(got - ref), 4 * DBL_EPSILON) << activation_name(a) << " at " << v;
    }
  }
}

TEST(Activation, SpecialValues) {
  EXPECT_EQ(activate(Activation::SignedSigmoid, 0.0), 0.0);
  EXPECT_EQ(activate(Activation::SignedSigmoid, kInf), 1.0);
  EXPECT_EQ(activate(Activation::SignedSigmoid, -kInf), -1.0);
  EXPECT_EQ(activate(Activation::SignedSigmoid, 800.0), 1.0);
  EXPECT_EQ(activate(Activation::SignedSigmoid, -800.0), -1.0);
  EXPECT_EQ(activate(Activation::Gaussian, 0.0), 1.0);
  EXPECT_EQ(bits(activate(Activation::Gaussian, 30.0)), bits(0.0));
  EXPECT_EQ(bits(activate(Activation::Gaussian, kInf)), bits(0.0));
  EXPECT_EQ(activate(Activation::SignedCosine, 0.0), 1.0);
  EXPECT_EQ(activate(Activation::SteepenedSigmoid, 0.0), 0.5);
  EXPECT_EQ(activate(Activation::SteepenedSigmoid, -kInf), 0.0);
  EXPECT_EQ(activate(Activation::SteepenedSigmoid, kInf), 1.0);
  for (int c = 0; c < kNumActivations; ++c) EXPECT_TRUE(std::isnan(activate(static_cast<Activation>(c), kNaN))) << c;
}

/// The bits of every activation and of math::tanh over a fixed set of
/// arguments. Recorded once; the same from gcc -O3, gcc -O0 and clang -O3.
uint64_t pinned_hash() {
  const std::vector<double> x = arguments(3, 100000);
  BitsHash h;
  for (int c = 0; c < kNumActivations; ++c)
    for (double v : x) h.add(activate(static_cast<Activation>(c), v));
  for (double v : x) h.add(math::tanh(v));
  for (double v : x) h.add(math::expm1(v));
  return h.h;
}

TEST(Activation, BitsArePinned) { EXPECT_EQ(pinned_hash(), 0x974b851d97bb5cb0ULL); }

}  // namespace
}  // namespace robozoo
