#include "evolve/neat/species/speciation.hpp"

#include <gtest/gtest.h>

#include "evolve/neat/population.hpp"
#include "evolve/neat/xor/xor_task.hpp"

namespace robozoo {
namespace {

// Genomes told apart by their link genes only (speciation looks at nothing else).
Genome with_links(int64_t id, std::vector<std::pair<int64_t, double>> genes) {
  Genome g;
  g.id = id;
  for (const auto& [innovation, w] : genes) g.links.push_back({innovation, 0, 3, w, true, 0});
  return g;
}

TEST(Speciate, GroupsByDistanceToTheFirstFittingRepresentative) {
  NeatParams p;  // c_d = c_e = 2, c_w = 1
  // A family {0,1,2} and a family {10,11,12}: 6 unmatched genes apart (distance 12).
  const std::vector<Genome> genomes = {
      with_links(0, {{0, 1.0}, {1, 1.0}, {2, 1.0}}),           with_links(1, {{10, 1.0}, {11, 1.0}, {12, 1.0}}),
      with_links(2, {{0, 1.5}, {1, 1.0}, {2, 1.0}}),            // distance 0.5 / 3 to genome 0
      with_links(3, {{0, 1.0}, {1, 1.0}, {2, 1.0}, {3, 0.0}}),  // one excess gene: 2
      with_links(4, {{10, -1.0}, {11, 1.0}, {12, 1.0}}),        // 2/3 to genome 1
  };
  std::vector<Species> species;
  int32_t next_id = 7;
  const auto of = speciate(genomes, species, 3.0, p, next_id, 4);
  ASSERT_EQ(species.size(), 2u);
  EXPECT_EQ(next_id, 9);
  EXPECT_EQ(of, (std::vector<int32_t>{7, 8, 7, 7, 8}));
  EXPECT_EQ(species[0].members, (std::vector<int>{0, 2, 3}));
  EXPECT_EQ(species[1].members, (std::vector<int>{1, 4}));
  EXPECT_EQ(species[0].representative, genomes[0]);
  EXPECT_EQ(species[1].representative, genomes[1]);
  EXPECT_EQ(species[0].age, 0);
  // HyperNEAT's stagnation (the default) counts the founding as the previous generation's
  // improvement; robozoo's as this generation's.
  EXPECT_EQ(species[0].last_improvement, 3);
  {
    NeatParams r = p;
    r.stagnation = StagnationRule::Robozoo;
    std::vector<Species> other;
    int32_t id = 0;
    speciate(genomes, other, 3.0, r, id, 4);
    EXPECT_EQ(other[0].last_improvement, 4);
  }

  // A lower threshold splits genome 3 off (distance 2 >= 1.5).
  species.clear();
  const auto of2 = speciate(genomes, species, 1.5, p, next_id, 4);
  EXPECT_EQ(species.size(), 3u);
  EXPECT_EQ(of2[3], 11);
}

TEST(Speciate, KeepsExistingSpeciesAndDropsEmptyOnes) {
  NeatParams p;
  std::vector<Species> species(2);
  species[0].id = 3;
  species[0].age = 5;
  species[0].representative = with_links(100, {{20, 0.0}});
  species[0].members = {0, 1, 2};
  species[1].id = 4;
  species[1].representative = with_links(101, {{0, 1.0}, {1, 1.0}});
  const std::vector<Genome> genomes = {with_links(0, {{0, 1.2}, {1, 1.0}}), with_links(1, {{0, 0.8}, {1, 1.0}})};
  int32_t next_id = 5;
  const auto of = speciate(genomes, species, 3.0, p, next_id, 9);
  ASSERT_EQ(species.size(), 1u) << "species 3 got no member and is gone";
  EXPECT_EQ(species[0].id, 4);
  EXPECT_EQ(of, (std::vector<int32_t>{4, 4}));
  EXPECT_EQ(next_id, 5);
}

TEST(AdjustThreshold, MovesTowardsTheTargetWithAFloor) {
  NeatParams p;                             // target 8, step 0.3, floor 0.3
  p.threshold_rule = ThresholdRule::Clamp;  // robozoo's; HyperNEAT's in hyperneat_test.cpp
  EXPECT_DOUBLE_EQ(adjust_threshold(6.0, 12, p), 6.3) << "too many species: threshold rises";
  EXPECT_DOUBLE_EQ(adjust_threshold(6.0, 3, p), 5.7) << "too few species: threshold falls";
  EXPECT_DOUBLE_EQ(adjust_threshold(6.0, 8, p), 6.0);
  EXPECT_DOUBLE_EQ(adjust_threshold(0.4, 1, p), 0.3);
  EXPECT_DOUBLE_EQ(adjust_threshold(0.3, 1, p), 0.3);
}

std::vector<double> xor_fitness(const Population& pop) {
  std::vector<double> f;
  for (const auto& g : pop.genomes()) f.push_back(evaluate_xor(g).fitness);
  return f;
}

TEST(AdjustThreshold, DrivesThePopulationTowardsTheTarget) {
  // One species at the start (initial genomes share every gene): the threshold
  // must fall until species appear.
  NeatParams p;
  Rng rng(4);
  Population pop(p, Regime::FeedForward, xor_layout(), rng);
  EXPECT_EQ(pop.species().size(), 1u);
  // Generation 0 was speciated with 6.0 (the threshold in force); the next one will use 5.7.
  EXPECT_DOUBLE_EQ(pop.speciation_threshold(), 6.0);
  EXPECT_DOUBLE_EQ(pop.compatibility_threshold(), 6.0 - 0.3);
  double lowest = pop.compatibility_threshold();
  size_t most = 0;
  for (int g = 0; g < 30; ++g) {
    const double next = pop.compatibility_threshold();
    pop.advance(xor_fitness(pop), rng);
    EXPECT_DOUBLE_EQ(pop.speciation_threshold(), next) << "generation " << g + 1;
    lowest = std::min(lowest, pop.compatibility_threshold());
    most = std::max(most, pop.species().size());
  }
  EXPECT_LT(lowest, 5.7);  // it fell more than once
  EXPECT_GE(most, 8u);

  // A target of 1 species: the threshold only rises while there are more.
  p.target_species = 1;
  Rng rng2(4);
  Population one(p, Regime::FeedForward, xor_layout(), rng2);
  double prev = one.compatibility_threshold();
  EXPECT_DOUBLE_EQ(prev, 6.0);
  for (int g = 0; g < 20; ++g) {
    one.advance(xor_fitness(one), rng2);
    const double now = one.compatibility_threshold();
    if (one.species().size() > 1) {
      EXPECT_DOUBLE_EQ(now, prev + 0.3);
    } else {
      EXPECT_DOUBLE_EQ(now, prev);
    }
    prev = now;
  }
}

}  // namespace
}  // namespace robozoo
