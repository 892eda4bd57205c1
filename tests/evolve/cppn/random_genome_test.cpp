#include "evolve/cppn/random_genome.hpp"

#include <gtest/gtest.h>

#include <set>
#include <stdexcept>
#include <utility>

#include "evolve/cppn/network.hpp"

namespace robozoo {
namespace {

TEST(RandomCppn, FullyConnectedStartWithoutHiddenNodes) {
  Rng rng(1);
  const GenomeLayout l = robot_layout();
  const Genome g = random_cppn(l, false, 0, 0, rng);
  EXPECT_NO_THROW(validate_genome(g, l));
  EXPECT_EQ(g.nodes.size(), 20u);
  ASSERT_EQ(g.links.size(), 99u);  // 9 inputs x 11 outputs
  std::set<std::pair<int, int>> pairs;
  for (const auto& link : g.links) {
    EXPECT_LT(link.from, l.num_inputs);
    EXPECT_GE(link.to, l.num_inputs);
    EXPECT_GE(link.weight, -3.0);
    EXPECT_LT(link.weight, 3.0);
    EXPECT_TRUE(link.enabled);
    pairs.emplace(link.from, link.to);
  }
  EXPECT_EQ(pairs.size(), 99u);
  EXPECT_EQ(g.nodes[4].kind, NodeKind::Bias);
}

TEST(RandomCppn, ValidUniqueAndAcyclicWhenFeedForward) {
  Rng rng(2);
  const GenomeLayout l = robot_layout();
  int cyclic_recurrent = 0, self_loops = 0;
  for (int i = 0; i < 400; ++i) {
    const bool recurrent = i % 2 == 1;
    const int hidden = i % 5, extra = i % 13;
    const Genome g = random_cppn(l, recurrent, hidden, extra, rng);
    ASSERT_NO_THROW(validate_genome(g, l));
    EXPECT_EQ(count_hidden(g), hidden);
    // Feed-forward without hidden nodes has no free pair left: every input is
    // already linked to every output, and outputs do not feed outputs.
    const int added = !recurrent && hidden == 0 ? 0 : extra;
    EXPECT_EQ(static_cast<int>(g.links.size()), 99 + 2 * hidden + added);
    std::set<std::pair<int, int>> pairs;
    for (size_t k = 0; k < g.links.size(); ++k) {
      EXPECT_EQ(g.links[k].innovation, static_cast<int64_t>(k));
      EXPECT_TRUE(pairs.emplace(g.links[k].from, g.links[k].to).second) << "duplicate link";
      self_loops += g.links[k].from == g.links[k].to;
    }
    for (const auto& n : g.nodes) {
      if (n.kind == NodeKind::Hidden) {
        EXPECT_LE(static_cast<int>(n.activation), 2);
      }
    }
    if (!recurrent) {
      EXPECT_FALSE(has_cycle(g));
    }
    cyclic_recurrent += recurrent && has_cycle(g);
    EXPECT_NO_THROW(Network(g, l));
  }
  EXPECT_GT(cyclic_recurrent, 20);  // the recurrent regime does make cycles
  EXPECT_GT(self_loops, 0);
}

TEST(RandomCppn, SameSeedSameGenome) {
  Rng a(7), b(7);
  for (int i = 0; i < 10; ++i) {
    const Genome x = random_cppn(robot_layout(), i % 2, 3, 8, a);
    const Genome y = random_cppn(robot_layout(), i % 2, 3, 8, b);
    EXPECT_EQ(genome_hash(x), genome_hash(y));
  }
  Rng c(8);
  Rng d(7);
  EXPECT_NE(genome_hash(random_cppn(robot_layout(), true, 3, 8, c)),
            genome_hash(random_cppn(robot_layout(), true, 3, 8, d)));
}

TEST(RandomCppn, StopsWhenNoPairIsLeft) {
  // One input (the bias), one output, feed-forward: the only pair is taken.
  GenomeLayout l;
  l.num_inputs = 1;
  l.bias_input = 0;
  l.num_outputs = 1;
  Rng rng(3);
  EXPECT_EQ(random_cppn(l, false, 0, 5, rng).links.size(), 1u);
  // Recurrent adds the output's self-loop, then nothing is left.
  EXPECT_EQ(random_cppn(l, true, 0, 5, rng).links.size(), 2u);
}

TEST(RandomCppn, RejectsNegativeCounts) {
  Rng rng(4);
  EXPECT_THROW(random_cppn(robot_layout(), false, -1, 0, rng), std::invalid_argument);
  EXPECT_THROW(random_cppn(robot_layout(), false, 0, -1, rng), std::invalid_argument);
}

}  // namespace
}  // namespace robozoo
