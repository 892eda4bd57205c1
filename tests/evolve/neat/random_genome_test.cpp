#include "evolve/neat/random_genome.hpp"

#include <gtest/gtest.h>

#include <set>
#include <stdexcept>
#include <utility>

#include "evolve/neat/initial_genome.hpp"

namespace robozoo {
namespace {

TEST(FullyRecurrentGenome, EveryInputToEveryOutputAndEveryOutputToEveryOther) {
  const GenomeLayout l = robot_layout();
  NeatParams neat;
  Rng rng(5);
  const Genome g = fully_recurrent_genome(l, 7, neat, rng);
  validate_genome(g, l);
  ASSERT_EQ(g.links.size(), 209u);
  EXPECT_EQ(g.nodes.size(), 20u);
  EXPECT_TRUE(has_cycle(g));
  std::set<std::pair<int, int>> pairs;
  for (const auto& link : g.links) {
    EXPECT_TRUE(link.enabled);
    EXPECT_NE(link.from, link.to) << "no self-loops";
    EXPECT_GE(link.to, l.num_inputs);
    EXPECT_GE(link.weight, -neat.initial_weight_range);
    EXPECT_LE(link.weight, neat.initial_weight_range);
    pairs.insert({link.from, link.to});
  }
  EXPECT_EQ(pairs.size(), 209u);
  EXPECT_EQ(g.links.back().innovation + 1, first_free_innovation_fully_recurrent(l));
  EXPECT_EQ(g.links[99].innovation, first_free_innovation(l));
}

TEST(FullyRecurrentGenome, EvolvedFromItKeepsItsCyclesAndIsDeterministic) {
  const GenomeLayout l = robot_layout();
  NeatParams neat;
  RandomGenomeParams rp;
  rp.rounds = 30;
  rp.fully_recurrent_start = true;
  Rng a(9), b(9);
  for (int i = 0; i < 20; ++i) {
    const Genome g = random_evolved_genome(l, Regime::Recurrent, neat, rp, a, i);
    validate_genome(g, l);
    EXPECT_TRUE(has_cycle(g));
    EXPECT_GE(g.links.size(), 209u);
    EXPECT_EQ(g, random_evolved_genome(l, Regime::Recurrent, neat, rp, b, i));
  }
  EXPECT_THROW(random_evolved_genome(l, Regime::FeedForward, neat, rp, a, 0), std::invalid_argument);
}

}  // namespace
}  // namespace robozoo
