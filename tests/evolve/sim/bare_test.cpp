// simulate_bare(): the benchmark's baseline. It returns nothing, so the tests
// check that it accepts what Simulation accepts and rejects what it rejects.
#include <gtest/gtest.h>

#include <stdexcept>

#include "evolve/sim/random_robot.hpp"
#include "evolve/sim/simulation.hpp"
#include "tests/evolve/sim/test_robots.hpp"

namespace robozoo {
namespace {

TEST(Bare, RunsHandBuiltAndRandomRobots) {
  EXPECT_NO_THROW(simulate_bare(test::flipper_sled(), SimParams{}, 200));
  Rng rng(4);
  for (int k = 0; k < 5; ++k) EXPECT_NO_THROW(simulate_bare(random_robot(rng, {}), SimParams{}, 100));
}

TEST(Bare, RejectsInvalidRobotsAndParameters) {
  Robot bad = test::flipper_sled();
  bad.spheres[3].density = -1;
  EXPECT_THROW(simulate_bare(bad, SimParams{}, 10), std::invalid_argument);
  SimParams p;
  p.dt = -0.01;
  EXPECT_THROW(simulate_bare(test::flipper_sled(), p, 10), std::invalid_argument);
}

}  // namespace
}  // namespace robozoo
