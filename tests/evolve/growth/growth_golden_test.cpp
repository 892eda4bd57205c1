// A golden hash of whole grown robots: random genomes of both regimes, including
// fully recurrent ones (cycles through every output), grown with the default
// parameters. It pins growth (every CPPN query, threshold, placement and weight)
// bit for bit across optimisations of the query path; it was last recorded with
// robozoo's own activation, sin and cos functions (evolve/math) and the touch
// tolerance of the placement rules. Two sets: M1/M2's settings (bias input 1.0,
// proportional weights, shared add-node numbers), whose hash is unchanged since
// those runs, so their logs still replay; and today's defaults (the authors' 0.3,
// HyperNEAT's rescaled weights and fresh add-node numbers).
#include <gtest/gtest.h>

#include <cstdint>

#include "evolve/core/rng.hpp"
#include "evolve/cppn/network.hpp"
#include "evolve/growth/growth.hpp"
#include "evolve/growth/robot_hash.hpp"
#include "evolve/neat/start/random_genome.hpp"

namespace robozoo {
namespace {

struct GoldenSet {
  uint64_t hash = 1469598103934665603ull;
  long long spheres = 0;
  int multi_sphere = 0;
};

void grow_set(GoldenSet& set, Regime regime, InitialLinks start, int count, uint64_t seed, NeatParams neat,
              const GrowthParams& growth) {
  neat.initial_links = start;
  RandomGenomeParams rp;
  rp.rounds = 30;
  Rng rng(seed);
  for (int i = 0; i < count; ++i) {
    const Genome g = random_evolved_genome(robot_layout(), regime, neat, rp, rng, i);
    Network net(g, robot_layout());
    const Robot r = grow(net, growth);
    set.hash = (set.hash ^ robot_hash(r)) * 1099511628211ull;
    set.spheres += static_cast<long long>(r.spheres.size());
    set.multi_sphere += r.spheres.size() > 1;
  }
}

GoldenSet grow_sets(const NeatParams& neat, const GrowthParams& growth) {
  GoldenSet set;
  grow_set(set, Regime::FeedForward, InitialLinks::AllAllowed, 60, 101, neat, growth);
  grow_set(set, Regime::Recurrent, InitialLinks::InputsToOutputs, 60, 202, neat, growth);
  grow_set(set, Regime::Recurrent, InitialLinks::AllAllowed, 30, 303, neat, growth);  // fully recurrent: 209 links
  return set;
}

TEST(GrowthGolden, RandomGenomesOfBothRegimesGrowTheRobotsRecordedWithM2sSettings) {
  NeatParams neat;
  neat.add_node_innovations = AddNodeInnovations::Shared;
  GrowthParams growth;
  growth.bias_input = 1.0;
  growth.weight_mapping = WeightMapping::Proportional;
  const GoldenSet set = grow_sets(neat, growth);
  // The set grows real robots, not roots alone.
  EXPECT_GT(set.multi_sphere, 40);
  EXPECT_GT(set.spheres, 1000);
  EXPECT_EQ(set.hash, 0x65f6cd09d7f57080ull)
      << std::hex << set.hash << std::dec << " spheres " << set.spheres << " multi " << set.multi_sphere;
}

TEST(GrowthGolden, RandomGenomesOfBothRegimesGrowTheRobotsRecordedWithTheDefaults) {
  const GoldenSet set = grow_sets(NeatParams{}, GrowthParams{});
  EXPECT_GT(set.multi_sphere, 40);
  EXPECT_GT(set.spheres, 1000);
  EXPECT_EQ(set.hash, 0x933785aa21b36f44ull)
      << std::hex << set.hash << std::dec << " spheres " << set.spheres << " multi " << set.multi_sphere;
}

}  // namespace
}  // namespace robozoo
