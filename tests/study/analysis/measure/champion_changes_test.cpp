#include "study/analysis/measure/champion_changes.hpp"

#include <gtest/gtest.h>

#include "tests/study/analysis/builders.hpp"

namespace robozoo {
namespace {

using namespace robozoo::testing;

// A run summary made directly: one champion per generation.
struct Gen {
  double fitness;
  int8_t outcome;
  std::vector<int32_t> parents;
  std::vector<double> radii;
};
RunSummary make_run(const std::vector<Gen>& gens) {
  RunSummary s;
  for (size_t g = 0; g < gens.size(); ++g) {
    const auto gen = static_cast<int32_t>(g);
    s.generations.push_back({gen, gens[g].fitness, 0.0, gens[g].fitness, 100.0 + gen});
    ChampionRecord c;
    c.generation = gen;
    c.genome = make_genome({{0, 0, 0}}, {}, 100 + gen, gen, gens[g].fitness, gens[g].outcome);
    c.morphology = make_morphology(gens[g].parents, gens[g].radii, {}, {}, 100 + gen, gen);
    c.has_morphology = true;
    s.champions.push_back(c);
  }
  return s;
}

TEST(ChampionChanges, NewChampionsTheirTopologyAndGain) {
  const RunSummary run = make_run({
      {3.0, 0, {-1}, {}},               // not simulated
      {15.0, 1, {-1, 0}, {}},           // gain from an unsimulated champion: left out
      {15.0, 1, {-1, 0}, {}},           // no gain: no new champion
      {15.25, 1, {-1, 0}, {0.1, 0.4}},  // same tree, other radii: same topology, +0.25
      {16.0, 1, {-1, 0, 0}, {}},        // a new branch: topology changed, +0.75
      {17.5, 1, {-1, 0, 1}, {}},        // the branch moved: changed, +1.5
  });
  const ChampionChanges c = champion_changes(run);
  ASSERT_EQ(c.changes.size(), 3u);
  EXPECT_EQ(c.not_simulated, 1);
  EXPECT_EQ(c.unknown, 0);
  EXPECT_EQ(c.changes[0].generation, 3);
  EXPECT_FALSE(c.changes[0].topology_changed);
  EXPECT_DOUBLE_EQ(c.changes[0].improvement, 0.25);
  EXPECT_EQ(c.changes[0].previous_id, 102);
  EXPECT_EQ(c.changes[0].genome_id, 103);
  EXPECT_TRUE(c.changes[1].topology_changed);
  EXPECT_DOUBLE_EQ(c.changes[1].improvement, 0.75);
  EXPECT_TRUE(c.changes[2].topology_changed);
  EXPECT_DOUBLE_EQ(c.changes[2].improvement, 1.5);

  ChampionChangeParams all;
  all.simulated_only = false;
  const ChampionChanges every = champion_changes(run, all);
  ASSERT_EQ(every.changes.size(), 4u);
  EXPECT_DOUBLE_EQ(every.changes[0].improvement, 12.0);
  EXPECT_TRUE(every.changes[0].topology_changed);
}

TEST(ChampionChanges, MissingChampionsAreCounted) {
  RunSummary run = make_run({{15.0, 1, {-1, 0}, {}}, {16.0, 1, {-1, 0}, {}}, {17.0, 1, {-1, 0}, {}}});
  run.champions[1].has_morphology = false;  // both changes touch generation 1
  const ChampionChanges c = champion_changes(run);
  EXPECT_TRUE(c.changes.empty());
  EXPECT_EQ(c.unknown, 2);
}

}  // namespace
}  // namespace robozoo
