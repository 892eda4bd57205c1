#include "study/analysis/measure/genotype_stats.hpp"

#include <gtest/gtest.h>

#include "tests/study/analysis/builders.hpp"

namespace robozoo {
namespace {

using testing::LinkSpec;
using testing::make_genome;
using testing::NodeSpec;

TEST(GenotypeStats, CountsNodesAndLinksByHand) {
  // Inputs 0, 1 (bias 4 kind 1) at position 0, outputs 9, 10 at 1; hidden 20 (sigmoid, 0.5),
  // 21 (cosine, 0.75), 22 (Gaussian, 0.6), 23 (Gaussian, 0.5).
  const cppn_genome_t g =
      make_genome({{0, 0, 0},
                   {4, 1, 0},
                   {9, 2, 0},
                   {10, 2, 0},
                   {20, 3, 0, 0.5},
                   {21, 3, 1, 0.75},
                   {22, 3, 2, 0.6},
                   {23, 3, 2, 0.5}},
                  {
                      {0, 20},         // forward (0 -> 0.5)
                      {20, 21},        // forward (0.5 -> 0.75), on the cycle 20 -> 21 -> 22 -> 20
                      {21, 22},        // recurrent (0.75 -> 0.6), on the cycle
                      {22, 20},        // recurrent (0.6 -> 0.5), on the cycle
                      {22, 9},         // forward (0.6 -> 1)
                      {23, 23},        // self-loop: recurrent, a cycle
                      {4, 10},         // forward
                      {10, 0, false},  // disabled: not expressed, so 0 -> ... -> 10 -> 0 is no cycle
                      {23, 10},        // forward
                  });
  const GenotypeStats s = genotype_stats(g);
  EXPECT_EQ(s.nodes, 8);
  EXPECT_EQ(s.hidden, 4);
  EXPECT_EQ(s.hidden_sigmoid, 1);
  EXPECT_EQ(s.hidden_cosine, 1);
  EXPECT_EQ(s.hidden_gaussian, 2);
  EXPECT_EQ(s.hidden_other, 0);
  EXPECT_EQ(s.link_genes, 9);
  EXPECT_EQ(s.links, 8);
  EXPECT_EQ(s.forward_links, 5);
  EXPECT_EQ(s.recurrent_links, 3);
  EXPECT_EQ(s.cycle_links, 4);
}

TEST(GenotypeStats, ForwardIsByPositionCyclesAreCountedApart) {
  const std::vector<NodeSpec> nodes = {{0, 0, 0}, {9, 2, 0}, {20, 3, 0}};
  const cppn_genome_t open = make_genome(nodes, {{0, 20}, {20, 9}, {9, 20, false}});
  const cppn_genome_t closed = make_genome(nodes, {{0, 20}, {20, 9}, {9, 20, true}});
  // 9 -> 20 goes from position 1 to 0.5: recurrent, enabled or not; enabling it closes a cycle.
  EXPECT_EQ(genotype_stats(open).forward_links, 2);
  EXPECT_EQ(genotype_stats(open).recurrent_links, 0);
  EXPECT_EQ(genotype_stats(open).cycle_links, 0);
  EXPECT_EQ(genotype_stats(closed).forward_links, 2);
  EXPECT_EQ(genotype_stats(closed).recurrent_links, 1);
  EXPECT_EQ(genotype_stats(closed).cycle_links, 2);
}

TEST(GenotypeStats, BadGenomesAreRefused) {
  EXPECT_THROW(genotype_stats(make_genome({{0, 0, 0}}, {{0, 7}})), std::invalid_argument);
  EXPECT_THROW(genotype_stats(make_genome({{0, 0, 0}, {0, 3, 0}}, {})), std::invalid_argument);
}

}  // namespace
}  // namespace robozoo
