#include "evolve/neat/species/compatibility.hpp"

#include <gtest/gtest.h>

#include "tests/evolve/neat/classic_params.hpp"

namespace robozoo {
namespace {

Genome with_links(std::vector<std::pair<int64_t, double>> genes) {
  Genome g;
  for (const auto& [innovation, w] : genes) g.links.push_back({innovation, 0, 3, w, true, 0});
  return g;
}

TEST(Compatibility, IdenticalGenomesAreAtDistanceZero) {
  const Genome a = with_links({{0, 1.0}, {1, -2.0}, {2, 0.5}});
  EXPECT_EQ(compatibility_distance(a, a, NeatParams{}), 0.0);
}

TEST(Compatibility, DisjointExcessAndWeightTermsWithNEqualToOne) {
  // a: 0 1 2 _ 5 _ _      b: 0 1 _ 3 4 _ 7 8
  // matching 0, 1 (|dw| = 1.0 and 3.0, mean 2.0);
  // disjoint: 2, 5 (a), 3, 4 (b) = 4; excess: 7, 8 (beyond a's last, 5) = 2.
  const Genome a = with_links({{0, 1.0}, {1, -2.0}, {2, 0.5}, {5, 4.0}});
  const Genome b = with_links({{0, 2.0}, {1, 1.0}, {3, 0.0}, {4, 0.0}, {7, 0.0}, {8, 0.0}});
  NeatParams p = classic_neat();  // c_d = 2, c_e = 2, c_w = 1
  EXPECT_DOUBLE_EQ(compatibility_distance(a, b, p), 2.0 * 4 + 2.0 * 2 + 1.0 * 2.0);
  EXPECT_DOUBLE_EQ(compatibility_distance(b, a, p), compatibility_distance(a, b, p));
  p.disjoint_coefficient = 1.0;
  p.excess_coefficient = 3.0;
  p.weight_coefficient = 0.5;
  EXPECT_DOUBLE_EQ(compatibility_distance(a, b, p), 1.0 * 4 + 3.0 * 2 + 0.5 * 2.0);
}

TEST(Compatibility, NoMatchingGenesMeansNoWeightTerm) {
  const Genome a = with_links({{0, 1.0}});
  const Genome b = with_links({{1, 4.0}, {2, 4.0}});
  // 0 is disjoint (b goes beyond it), 1 and 2 are excess.
  EXPECT_DOUBLE_EQ(compatibility_distance(a, b, classic_neat()), 2.0 * 1 + 2.0 * 2);
  EXPECT_DOUBLE_EQ(compatibility_distance(a, Genome{}, classic_neat()), 2.0);
}

TEST(Compatibility, DisabledGenesCountLikeEnabledOnes) {
  Genome a = with_links({{0, 1.0}, {1, 1.0}});
  Genome b = a;
  b.links[1].enabled = false;
  EXPECT_EQ(compatibility_distance(a, b, NeatParams{}), 0.0);
}

TEST(Compatibility, HyperNeatCountsExcessAsTheDifferenceInSize) {
  // HyperNEAT's getCompatibility: walk both lists while both have genes; every
  // unmatched gene met is disjoint; excess = |#a - #b|, whatever the innovations.
  // a: 0 1 2 3      b: 0 7 8
  // walk: 0 matches (|dw| = 0.5); 1, 2, 3 < 7 are disjoint; a ends. D = 3, E = |4 - 3| = 1.
  const Genome a = with_links({{0, 1.0}, {1, 0.0}, {2, 0.0}, {3, 0.0}});
  const Genome b = with_links({{0, 1.5}, {7, 0.0}, {8, 0.0}});
  NeatParams p;  // HyperNEAT's rule and coefficients c_d = 2, c_e = 2, c_w = 1
  ASSERT_EQ(p.compatibility, CompatibilityRule::HyperNeat);
  EXPECT_DOUBLE_EQ(compatibility_distance(a, b, p), 2.0 * 3 + 2.0 * 1 + 1.0 * 0.5);
  EXPECT_DOUBLE_EQ(compatibility_distance(b, a, p), compatibility_distance(a, b, p));
  // The classic count on the same pair: D = 3, E = 2 (7 and 8 lie beyond a's last gene).
  EXPECT_DOUBLE_EQ(compatibility_distance(a, b, classic_neat()), 2.0 * 3 + 2.0 * 2 + 1.0 * 0.5);
  // a: 0      b: 1 2  ->  walk: 0 < 1 disjoint, a ends: D = 1, E = 1, no weight term.
  EXPECT_DOUBLE_EQ(compatibility_distance(with_links({{0, 1.0}}), with_links({{1, 4.0}, {2, 4.0}}), p),
                   2.0 * 1 + 2.0 * 1);
  // Same size, same innovations shifted: no excess at all, every gene disjoint.
  // a: 0 1      b: 2 3  -> walk: 0, 1 disjoint, a ends: D = 2, E = 0.
  EXPECT_DOUBLE_EQ(compatibility_distance(with_links({{0, 1.0}, {1, 1.0}}), with_links({{2, 1.0}, {3, 1.0}}), p),
                   2.0 * 2);
}

}  // namespace
}  // namespace robozoo
