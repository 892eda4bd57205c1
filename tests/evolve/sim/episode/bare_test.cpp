// simulate_bare(): the benchmark's baseline. The tests check that it accepts what
// Simulation accepts and rejects what it rejects, and that the contacts it
// counts are the ones a simulation of the same world hands to the solver.
#include <gtest/gtest.h>

#include <stdexcept>

#include "evolve/sim/robots/random_robot.hpp"
#include "evolve/sim/episode/simulation.hpp"
#include "tests/evolve/sim/test_robots.hpp"

namespace robozoo {
namespace {

TEST(Bare, RunsHandBuiltAndRandomRobots) {
  EXPECT_NO_THROW(simulate_bare(test::flipper_sled(), SimParams{}, 200));
  Rng rng(4);
  for (int k = 0; k < 5; ++k) EXPECT_NO_THROW(simulate_bare(random_robot(rng, {}), SimParams{}, 100));
}

TEST(Bare, CountsTheContactsASimulationOfTheSameWorldSees) {
  // One sphere: no joints, so no controller acts, and the bare loop steps the
  // same world as a simulation, from the same solver seed.
  const Robot r = test::single_sphere();
  SimParams p;
  p.steps = 300;
  Simulation sim(r, p);
  sim.enable_timing(true);
  while (sim.step()) {
  }
  const int steps = sim.result().steps_run;
  const long long bare = simulate_bare(r, p, steps);
  EXPECT_EQ(bare, sim.timing().contacts);
  EXPECT_GT(bare, 0);      // it lands on the ground and rests there
  EXPECT_LE(bare, steps);  // a sphere on a plane: at most one contact a step
  EXPECT_EQ(simulate_bare(r, p, 0), 0);
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
