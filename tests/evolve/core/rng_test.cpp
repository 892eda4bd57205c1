#include "evolve/core/rng.hpp"

#include <gtest/gtest.h>

namespace robozoo {
namespace {

TEST(Rng, SameSeedSameSequence) {
  Rng a(42), b(42), c(43);
  bool differs = false;
  for (int i = 0; i < 100; ++i) {
    const uint64_t x = a.next_u64();
    EXPECT_EQ(x, b.next_u64());
    differs |= x != c.next_u64();
  }
  EXPECT_TRUE(differs);
}

TEST(Rng, KnownFirstValue) {
  // mt19937_64's 10000th output for the default seed is fixed by the C++ standard;
  // our first output for seed 5489 is the engine's first output.
  Rng r(5489);
  EXPECT_EQ(r.next_u64(), 14514284786278117030ull);
}

TEST(Rng, UniformRanges) {
  Rng r(7);
  for (int i = 0; i < 10000; ++i) {
    const double u = r.uniform();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    const double v = r.uniform(-3.0, 3.0);
    ASSERT_GE(v, -3.0);
    ASSERT_LT(v, 3.0);
    const int64_t k = r.uniform_int(-2, 2);
    ASSERT_GE(k, -2);
    ASSERT_LE(k, 2);
  }
}

TEST(Rng, UniformIntCoversRange) {
  Rng r(9);
  int seen[5] = {0, 0, 0, 0, 0};
  for (int i = 0; i < 5000; ++i) ++seen[r.uniform_int(0, 4)];
  for (int c : seen) EXPECT_GT(c, 800);
}

TEST(Rng, StateRoundTrip) {
  Rng a(123);
  for (int i = 0; i < 10; ++i) a.next_u64();
  Rng b(0);
  b.set_state(a.state());
  for (int i = 0; i < 10; ++i) EXPECT_EQ(a.next_u64(), b.next_u64());
  EXPECT_THROW(b.set_state("not a state"), std::invalid_argument);
}

}  // namespace
}  // namespace robozoo
