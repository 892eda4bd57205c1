#include "evolve/neat/variation/innovation.hpp"

#include <gtest/gtest.h>

namespace robozoo {
namespace {

TEST(InnovationTracker, SameLinkInOneGenerationGetsTheSameNumber) {
  InnovationTracker t(100, 20);
  const int64_t a = t.link(0, 20);
  const int64_t b = t.link(3, 21);
  EXPECT_EQ(a, 100);
  EXPECT_EQ(b, 101);
  EXPECT_EQ(t.link(0, 20), a);
  EXPECT_EQ(t.link(3, 21), b);
  EXPECT_NE(t.link(20, 0), a) << "direction matters";
  EXPECT_EQ(t.next_innovation(), 103);
}

TEST(InnovationTracker, NewGenerationGivesFreshNumbers) {
  InnovationTracker t(10, 5);
  const int64_t a = t.link(1, 4);
  const auto s = t.split(7, 1, 4, Activation::Gaussian);
  t.new_generation();
  const int64_t a2 = t.link(1, 4);
  const auto s2 = t.split(7, 1, 4, Activation::SignedCosine);
  EXPECT_GT(a2, a);
  EXPECT_GT(s2.node, s.node);
  EXPECT_GT(s2.in_link, s.out_link);
  EXPECT_EQ(s2.activation, Activation::SignedCosine);
}

TEST(InnovationTracker, SameSplitInOneGenerationGetsTheSameNodeLinksAndActivation) {
  InnovationTracker t(50, 30);
  const auto s = t.split(3, 0, 9, Activation::Gaussian);
  EXPECT_EQ(s.node, 30);
  EXPECT_EQ(s.in_link, 50);
  EXPECT_EQ(s.out_link, 51);
  const auto again = t.split(3, 0, 9, Activation::SignedSigmoid);
  EXPECT_EQ(again.node, s.node);
  EXPECT_EQ(again.in_link, s.in_link);
  EXPECT_EQ(again.out_link, s.out_link);
  EXPECT_EQ(again.activation, Activation::Gaussian) << "the first split fixes the activation";
  const auto other = t.split(4, 1, 9, Activation::SignedSigmoid);
  EXPECT_EQ(other.node, 31);
  EXPECT_EQ(other.in_link, 52);
  EXPECT_EQ(t.next_node_id(), 32);
  EXPECT_EQ(t.next_innovation(), 54);
  // The split's links are registered as this generation's link innovations.
  EXPECT_EQ(t.link(0, 30), s.in_link);
  EXPECT_EQ(t.link(30, 9), s.out_link);
  EXPECT_EQ(t.next_innovation(), 54);
}

TEST(InnovationTracker, FreshSplitsOfTheSameLinkGetNewNumbersEachTime) {
  InnovationTracker t(50, 30);
  const auto a = t.fresh_split(0, 9, Activation::Gaussian);
  const auto b = t.fresh_split(0, 9, Activation::SignedSigmoid);
  EXPECT_EQ(a.node, 30);
  EXPECT_EQ(a.in_link, 50);
  EXPECT_EQ(a.out_link, 51);
  EXPECT_EQ(a.activation, Activation::Gaussian);
  EXPECT_EQ(b.node, 31) << "HyperNEAT: every split a new node";
  EXPECT_EQ(b.in_link, 52);
  EXPECT_EQ(b.out_link, 53);
  EXPECT_EQ(b.activation, Activation::SignedSigmoid) << "each split keeps its own activation";
  EXPECT_EQ(t.next_node_id(), 32);
  EXPECT_EQ(t.next_innovation(), 54);
  // The new links are this generation's link innovations: add-link of the same pair reuses them.
  EXPECT_EQ(t.link(0, 30), a.in_link);
  EXPECT_EQ(t.link(31, 9), b.out_link);
  EXPECT_EQ(t.next_innovation(), 54);
}

}  // namespace
}  // namespace robozoo
