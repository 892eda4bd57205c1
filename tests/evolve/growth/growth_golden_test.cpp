// A golden hash of whole grown robots: random genomes of both regimes, including
// fully recurrent ones (cycles through every output), grown with the default
// parameters. It pins growth (every CPPN query, threshold, placement and weight)
// bit for bit across optimisations of the query path; it was last recorded with
// robozoo's own activation, sin and cos functions (evolve/math) and the touch
// tolerance of the placement rules.
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

void grow_set(GoldenSet& set, Regime regime, InitialLinks start, int count, uint64_t seed) {
  NeatParams neat;
  neat.initial_links = start;
  RandomGenomeParams rp;
  rp.rounds = 30;
  Rng rng(seed);
  for (int i = 0; i < count; ++i) {
    const Genome g = random_evolved_genome(robot_layout(), regime, neat, rp, rng, i);
    Network net(g, robot_layout());
    const Robot r = grow(net, GrowthParams{});
    set.hash = (set.hash ^ robot_hash(r)) * 1099511628211ull;
    set.spheres += static_cast<long long>(r.spheres.size());
    set.multi_sphere += r.spheres.size() > 1;
  }
}

TEST(GrowthGolden, RandomGenomesOfBothRegimesGrowTheRecordedRobots) {
  GoldenSet set;
  grow_set(set, Regime::FeedForward, InitialLinks::AllAllowed, 60, 101);
  grow_set(set, Regime::Recurrent, InitialLinks::InputsToOutputs, 60, 202);
  grow_set(set, Regime::Recurrent, InitialLinks::AllAllowed, 30, 303);  // fully recurrent: 209 links
  // The set grows real robots, not roots alone.
  EXPECT_GT(set.multi_sphere, 40);
  EXPECT_GT(set.spheres, 1000);
  EXPECT_EQ(set.hash, 0x65f6cd09d7f57080ull)
      << std::hex << set.hash << std::dec << " spheres " << set.spheres << " multi " << set.multi_sphere;
}

}  // namespace
}  // namespace robozoo
