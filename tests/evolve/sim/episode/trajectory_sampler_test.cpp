// The one trajectory sampler: which steps it samples, and that each sample is
// the simulation's state at that step.
#include "evolve/sim/episode/trajectory_sampler.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "evolve/core/rng.hpp"
#include "evolve/sim/robots/random_robot.hpp"

namespace robozoo {
namespace {

TEST(TrajectorySampler, StepsAreZeroEveryKthAndTheLast) {
  EXPECT_EQ(trajectory_steps(10, 4), (std::vector<int32_t>{0, 4, 8, 10}));
  EXPECT_EQ(trajectory_steps(8, 4), (std::vector<int32_t>{0, 4, 8}));
  EXPECT_EQ(trajectory_steps(3, 1), (std::vector<int32_t>{0, 1, 2, 3}));
  EXPECT_EQ(trajectory_steps(0, 4), (std::vector<int32_t>{0}));
  EXPECT_EQ(trajectory_steps(2, 5), (std::vector<int32_t>{0, 2}));
  EXPECT_THROW(trajectory_steps(10, 0), std::invalid_argument);
}

Robot six_spheres() {
  Rng rng(3);
  RandomRobotParams rp;
  rp.min_spheres = rp.max_spheres = 6;
  return random_robot(rng, rp);
}

// Every sample is the state a plain step loop sees at that step, bit for bit,
// and the result is the plain loop's.
TEST(TrajectorySampler, SamplesTheStatesOfThoseStepsAndReturnsTheResult) {
  const Robot robot = six_spheres();
  SimParams params;
  params.steps = 203;
  std::vector<SimState> every_state;
  Simulation plain(robot, params);
  every_state.push_back(plain.state());
  while (plain.step()) every_state.push_back(plain.state());
  const SimResult want = plain.result();
  ASSERT_EQ(static_cast<int>(every_state.size()), want.steps_run + 1);
  for (int k : {1, 4, 7, 500}) {
    Simulation sim(robot, params);
    std::vector<SimState> samples;
    const SimResult got = sample_trajectory(sim, k, [&](const SimState& s) { samples.push_back(s); });
    EXPECT_EQ(got.steps_run, want.steps_run);
    EXPECT_EQ(got.d, want.d);
    EXPECT_EQ(got.outcome, want.outcome);
    const std::vector<int32_t> steps = trajectory_steps(got.steps_run, k);
    ASSERT_EQ(samples.size(), steps.size()) << "k = " << k;
    for (size_t i = 0; i < steps.size(); ++i) {
      const SimState& expected = every_state[static_cast<size_t>(steps[i])];
      EXPECT_EQ(samples[i].step, steps[i]);
      EXPECT_EQ(samples[i].time, expected.time);
      EXPECT_EQ(samples[i].sphere_center, expected.sphere_center);
      EXPECT_EQ(samples[i].neuron_output, expected.neuron_output);
      EXPECT_EQ(samples[i].sensor_value, expected.sensor_value);
    }
  }
}

TEST(TrajectorySampler, RefusesEveryBelowOneBeforeStepping) {
  Simulation sim(six_spheres(), SimParams{});
  int calls = 0;
  EXPECT_THROW(sample_trajectory(sim, 0, [&](const SimState&) { ++calls; }), std::invalid_argument);
  EXPECT_EQ(calls, 0);
  EXPECT_EQ(sim.state().step, 0);
}

}  // namespace
}  // namespace robozoo
