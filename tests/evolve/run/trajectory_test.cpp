// A champion's logged trajectory: which steps it holds, that the simulation
// gives exactly those poses, and the key that decides whether a champion's
// trajectory is logged at all.
#include "evolve/run/trajectory.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

#include "evolve/neat/start/initial_genome.hpp"
#include "evolve/neat/population.hpp"
#include "evolve/sim/robots/random_robot.hpp"

namespace robozoo {
namespace {

TEST(PoseStream, TheSimulationLogsExactlyThoseSteps) {
  Rng rng(3);
  RandomRobotParams rp;
  rp.min_spheres = rp.max_spheres = 6;
  const Robot robot = random_robot(rng, rp);
  SimParams sim;
  sim.steps = 203;
  for (int k : {1, 4, 7}) {
    const PoseStream t = simulate_pose_stream(robot, sim, k, "run", 2, 17);
    ASSERT_GT(t.result.steps_run, 0);
    const auto steps = trajectory_steps(t.result.steps_run, k);
    ASSERT_EQ(t.poses.size(), steps.size()) << "k = " << k;
    for (size_t i = 0; i < steps.size(); ++i) {
      EXPECT_EQ(t.poses[i].step, steps[i]);
      EXPECT_EQ(t.poses[i].genome_id, 17);
      EXPECT_EQ(t.poses[i].generation, 2);
      EXPECT_EQ(t.poses[i].utime, 0);
    }
  }
  EXPECT_THROW(simulate_pose_stream(robot, sim, 0, "run", 0, 0), std::invalid_argument);
}

TEST(PoseStream, TheKeyIgnoresIdAndBirthButNotGenes) {
  Rng rng(5);
  const Genome g = initial_genome(robot_layout(), 11, NeatParams{}, Regime::Recurrent, rng);
  Genome copy = g;
  copy.id = 99;
  for (auto& l : copy.links) l.born = 7;
  EXPECT_EQ(trajectory_key(copy), trajectory_key(g));
  Genome changed = g;
  changed.links[3].weight += 1e-12;
  EXPECT_NE(trajectory_key(changed), trajectory_key(g));
  Genome disabled = g;
  disabled.links[0].enabled = !disabled.links[0].enabled;
  EXPECT_NE(trajectory_key(disabled), trajectory_key(g));
}

}  // namespace
}  // namespace robozoo
