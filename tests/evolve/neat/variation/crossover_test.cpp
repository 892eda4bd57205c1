#include "evolve/neat/variation/crossover.hpp"

#include <gtest/gtest.h>

#include "tests/evolve/neat/tiny_genome.hpp"

namespace robozoo {
namespace {

Genome base(int64_t id) { return test::tiny_genome(id, Activation::SignedSigmoid); }

// a: 0->3 (0), 1->3 (1), 2->3 (2, disabled), 0->4 (3), 4->3 (4); hidden 4.
Genome parent_a() {
  Genome g = base(1);
  g.nodes.push_back({4, NodeKind::Hidden, Activation::Gaussian});
  g.links = {{0, 0, 3, 1.0, true, 0},
             {1, 1, 3, 2.0, true, 0},
             {2, 2, 3, 3.0, false, 0},
             {3, 2, 4, 1.0, true, 1},
             {4, 4, 3, 3.0, true, 1}};
  return g;
}
// b: 0->3 (0), 1->3 (1), 2->3 (2), 1->5 (5), 5->3 (6), 0->3 ... ; hidden 5.
Genome parent_b() {
  Genome g = base(2);
  g.nodes.push_back({5, NodeKind::Hidden, Activation::SignedCosine});
  g.links = {{0, 0, 3, -1.0, true, 0}, {1, 1, 3, -2.0, false, 0}, {2, 2, 3, -3.0, true, 0},
             {5, 1, 5, 1.0, true, 2},  {6, 5, 3, -1.0, true, 2},  {9, 0, 5, 0.5, true, 3}};
  return g;
}

std::vector<int64_t> innovations(const Genome& g) {
  std::vector<int64_t> v;
  for (const auto& l : g.links) v.push_back(l.innovation);
  return v;
}

TEST(Crossover, ChildHasTheFitterParentsStructure) {
  const Genome a = parent_a(), b = parent_b();
  Rng rng(5);
  for (int k = 0; k < 50; ++k) {
    const Genome c1 = crossover(a, 2.0, b, 1.0, rng);
    EXPECT_EQ(c1.nodes, a.nodes);
    EXPECT_EQ(innovations(c1), innovations(a)) << "disjoint/excess genes of b must not appear";
    validate_genome(c1, test::tiny_layout());
    EXPECT_EQ(c1.id, -1);
    const Genome c2 = crossover(a, 1.0, b, 2.0, rng);
    EXPECT_EQ(c2.nodes, b.nodes);
    EXPECT_EQ(innovations(c2), innovations(b)) << "disjoint/excess genes of a must not appear";
    validate_genome(c2, test::tiny_layout());
    const Genome c3 = crossover(a, 1.0, b, 1.0, rng);
    EXPECT_EQ(innovations(c3), innovations(a)) << "equal fitness: the first parent's structure";
  }
}

TEST(Crossover, MatchingGenesComeWholeFromEitherParent) {
  const Genome a = parent_a(), b = parent_b();
  Rng rng(9);
  int from_a[3] = {0, 0, 0}, from_b[3] = {0, 0, 0};
  const int trials = 400;
  for (int k = 0; k < trials; ++k) {
    const Genome c = crossover(a, 2.0, b, 1.0, rng);
    for (int i = 0; i < 3; ++i) {
      const LinkGene& l = c.links[static_cast<size_t>(i)];
      if (l == a.links[static_cast<size_t>(i)])
        ++from_a[i];
      else if (l == b.links[static_cast<size_t>(i)])
        ++from_b[i];
      else
        ADD_FAILURE() << "matching gene " << i << " mixes the parents' genes";
    }
    // Non-matching genes of the fitter parent are copied unchanged.
    EXPECT_EQ(c.links[3], a.links[3]);
    EXPECT_EQ(c.links[4], a.links[4]);
  }
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(from_a[i] + from_b[i], trials);
    EXPECT_GT(from_a[i], trials / 2 - 60);
    EXPECT_GT(from_b[i], trials / 2 - 60);
  }
}

TEST(Crossover, SameInnovationWithDifferentEndpointsIsAnInvariantViolation) {
  Genome a = parent_a(), b = parent_b();
  b.links[0].from = 1;
  Rng rng(1);
  EXPECT_THROW(crossover(a, 2.0, b, 1.0, rng), std::logic_error);
}

TEST(Crossover, ClassicNeatInheritsADisabledGeneDisabledThreeTimesInFour) {
  // Gene 2 is disabled in a, gene 1 in b: matching genes disabled in either
  // parent. With probability 0.75 each is inherited disabled, else enabled,
  // whichever parent's copy was drawn; genes enabled in both stay enabled.
  NeatParams p;
  p.crossover_genes = CrossoverGenes::Fitter;  // robozoo's crossover, the rule's home
  p.disabled_gene_probability = 0.75;
  Rng rng(31);
  const int n = 4000;
  int disabled1 = 0, disabled2 = 0;
  for (int k = 0; k < n; ++k) {
    const Genome c = crossover(parent_a(), 2.0, parent_b(), 1.0, p, rng);
    ASSERT_TRUE(c.links[0].enabled);
    disabled1 += !c.links[1].enabled;
    disabled2 += !c.links[2].enabled;
    ASSERT_TRUE(c.links[3].enabled && c.links[4].enabled);
  }
  // Binomial(4000, 0.75): mean 3000, sd 27.4; +-5 sd.
  EXPECT_NEAR(disabled1, 3000, 137);
  EXPECT_NEAR(disabled2, 3000, 137);
  // Probability 0 (HyperNEAT, the default): the drawn gene as it is, no extra draw.
  Rng r1(32), r2(32);
  const Genome plain = crossover(parent_a(), 2.0, parent_b(), 1.0, r1);
  NeatParams zero_probability;  // the default, 0
  zero_probability.crossover_genes = CrossoverGenes::Fitter;
  const Genome zero = crossover(parent_a(), 2.0, parent_b(), 1.0, zero_probability, r2);
  EXPECT_EQ(plain, zero);
  EXPECT_EQ(r1.state(), r2.state());
}

}  // namespace
}  // namespace robozoo
