#include "evolve/neat/initial_genome.hpp"

#include <gtest/gtest.h>

#include <set>

namespace robozoo {
namespace {

TEST(InitialGenome, LinksEveryInputToEveryOutputWithSharedInnovations) {
  const GenomeLayout layout = robot_layout();
  NeatParams p;
  Rng rng(3);
  const Genome a = initial_genome(layout, 0, p, rng);
  const Genome b = initial_genome(layout, 1, p, rng);
  validate_genome(a, layout);
  EXPECT_EQ(a.id, 0);
  EXPECT_EQ(b.id, 1);
  EXPECT_EQ(count_hidden(a), 0);
  ASSERT_EQ(a.links.size(), static_cast<size_t>(layout.num_inputs * layout.num_outputs));
  EXPECT_EQ(a.nodes.size(), static_cast<size_t>(layout.num_inputs + layout.num_outputs));
  EXPECT_EQ(a.nodes[4].kind, NodeKind::Bias);
  EXPECT_EQ(a.nodes[9].kind, NodeKind::Output);
  std::set<std::pair<int, int>> pairs;
  bool weights_differ = false;
  for (size_t k = 0; k < a.links.size(); ++k) {
    const LinkGene& l = a.links[k];
    EXPECT_EQ(l.innovation, initial_link_innovation(layout, l.from, l.to - layout.num_inputs));
    EXPECT_EQ(l.innovation, b.links[k].innovation);
    EXPECT_EQ(l.from, b.links[k].from);
    EXPECT_EQ(l.to, b.links[k].to);
    EXPECT_TRUE(l.enabled);
    EXPECT_EQ(l.born, 0);
    EXPECT_GE(l.weight, -p.initial_weight_range);
    EXPECT_LE(l.weight, p.initial_weight_range);
    weights_differ |= l.weight != b.links[k].weight;
    pairs.insert({l.from, l.to});
  }
  EXPECT_EQ(pairs.size(), a.links.size());
  EXPECT_TRUE(weights_differ);
  EXPECT_EQ(first_free_innovation(layout), 99);
}

TEST(InitialGenome, WeightsCoverTheirRange) {
  GenomeLayout layout;
  layout.num_inputs = 3;
  layout.bias_input = 2;
  layout.num_outputs = 1;
  NeatParams p;
  Rng rng(11);
  double lo = 0, hi = 0;
  for (int i = 0; i < 300; ++i)
    for (const auto& l : initial_genome(layout, i, p, rng).links) {
      lo = std::min(lo, l.weight);
      hi = std::max(hi, l.weight);
    }
  EXPECT_LT(lo, -2.8);
  EXPECT_GT(hi, 2.8);
}

TEST(InitialGenome, RejectsEmptyLayouts) {
  GenomeLayout layout;
  layout.num_outputs = 0;
  NeatParams p;
  Rng rng(1);
  EXPECT_THROW(initial_genome(layout, 0, p, rng), std::invalid_argument);
}

}  // namespace
}  // namespace robozoo
