#include "evolve/neat/species/reproduction.hpp"

#include <gtest/gtest.h>

#include <numeric>

#include "evolve/core/rng.hpp"

namespace robozoo {
namespace {

int sum(const std::vector<int>& v) { return std::accumulate(v.begin(), v.end(), 0); }

TEST(AllocateOffspring, SumsExactlyToTheTotal) {
  Rng rng(1);
  for (int trial = 0; trial < 2000; ++trial) {
    const size_t n = 1 + rng.index(20);
    std::vector<double> shares(n), sizes(n, 1.0);
    for (auto& s : shares) s = rng.bernoulli(0.2) ? 0.0 : rng.uniform(0.0, 16.0) * (rng.bernoulli(0.2) ? 0.001 : 1.0);
    const int total = static_cast<int>(1 + rng.index(300));
    const auto counts = allocate_offspring(shares, total, sizes);
    ASSERT_EQ(sum(counts), total);
    double all = 0;
    for (double s : shares) all += s;
    for (size_t i = 0; i < n; ++i) {
      ASSERT_GE(counts[i], 0);
      if (all > 0) {
        // Largest remainder: within one of the exact quota.
        const double quota = shares[i] / all * total;
        ASSERT_LT(std::abs(counts[i] - quota), 1.0 + 1e-9);
        if (shares[i] == 0.0) {
          ASSERT_EQ(counts[i], 0);
        }
      }
    }
  }
}

TEST(AllocateOffspring, ProportionalLargestRemainder) {
  EXPECT_EQ(allocate_offspring({1.0, 1.0, 2.0}, 8, {1, 1, 1}), (std::vector<int>{2, 2, 4}));
  // Quotas 3.33.., 3.33.., 3.33..: the remainder goes to the first.
  EXPECT_EQ(allocate_offspring({1.0, 1.0, 1.0}, 10, {1, 1, 1}), (std::vector<int>{4, 3, 3}));
  // Quotas 0.5, 1.5, 2.0 (shares 1, 3, 4 of 8): equal fractions, the lower index first.
  EXPECT_EQ(allocate_offspring({1.0, 3.0, 4.0}, 4, {1, 1, 1}), (std::vector<int>{1, 1, 2}));
  // Quotas 2.25, 0.75, 1.0: the larger fraction wins.
  EXPECT_EQ(allocate_offspring({9.0, 3.0, 4.0}, 4, {1, 1, 1}), (std::vector<int>{2, 1, 1}));
  EXPECT_EQ(allocate_offspring({0.0, 5.0}, 150, {1, 1}), (std::vector<int>{0, 150}));
}

TEST(AllocateOffspring, AllZeroSharesFallBackAndBadInputThrows) {
  EXPECT_EQ(allocate_offspring({0.0, 0.0}, 10, {3.0, 7.0}), (std::vector<int>{3, 7}));
  EXPECT_THROW(allocate_offspring({-1.0, 2.0}, 10, {1, 1}), std::invalid_argument);
  EXPECT_THROW(allocate_offspring({1.0}, 10, {1, 1}), std::invalid_argument);
  EXPECT_THROW(allocate_offspring({0.0}, 10, {0.0}), std::invalid_argument);
  EXPECT_THROW(allocate_offspring({std::nan("")}, 10, {1.0}), std::invalid_argument);
}

Species species_with(std::vector<int> members, int32_t last_improvement) {
  Species s;
  s.members = std::move(members);
  s.last_improvement = last_improvement;
  return s;
}

TEST(FitnessSharing, SharedFitnessIsTheMeanAndDropsOffWhenStagnant) {
  NeatParams p;  // drop-off age 15, factor 0.001
  const std::vector<double> f = {4.0, 1.0, 9.0, 2.0, 0.0};
  const Species s = species_with({0, 2, 3}, 10);
  EXPECT_DOUBLE_EQ(species_adjusted_fitness(s, f, 24, p), 4.0 / 3 + 9.0 / 3 + 2.0 / 3);
  EXPECT_FALSE(is_stagnant(s, 24, p));
  EXPECT_TRUE(is_stagnant(s, 25, p));
  EXPECT_DOUBLE_EQ(species_adjusted_fitness(s, f, 25, p), 0.001 * (4.0 / 3 + 9.0 / 3 + 2.0 / 3));
  // A big species with the same members' fitness gets the same share as a small one.
  const std::vector<double> same(10, 3.0);
  EXPECT_DOUBLE_EQ(species_adjusted_fitness(species_with({0, 1, 2, 3, 4, 5, 6, 7}, 0), same, 0, p),
                   species_adjusted_fitness(species_with({8, 9}, 0), same, 0, p));
}

TEST(NumParents, SurvivalThreshold) {
  NeatParams p;  // 0.2
  EXPECT_EQ(num_parents(1, p), 1);
  EXPECT_EQ(num_parents(4, p), 1);
  EXPECT_EQ(num_parents(5, p), 2);
  EXPECT_EQ(num_parents(50, p), 11);
  p.survival_threshold = 1.0;
  EXPECT_EQ(num_parents(7, p), 7);
}

}  // namespace
}  // namespace robozoo
