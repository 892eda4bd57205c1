#include "evolve/sim/episode/simulation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "evolve/sim/robots/robot_builder.hpp"
#include "tests/evolve/sim/test_robots.hpp"

namespace robozoo {
namespace {

SimParams no_rolling_rules() {
  SimParams p;
  p.rolling_contact_rule = false;
  p.rolling_spin_rule = false;
  return p;
}

TEST(Simulation, ASphereAtRestStopsEarly) {
  const SimResult r = simulate(test::single_sphere(), no_rolling_rules());
  EXPECT_EQ(r.outcome, Outcome::StoppedEarly);
  EXPECT_TRUE(r.stopped_early);
  EXPECT_LT(r.steps_run, 200);
  EXPECT_GE(r.steps_run, SimParams{}.rest_steps);
  EXPECT_NEAR(r.d, 0.0, 1e-3);
  // With the default rules the resting sphere touched the ground every step:
  // rule (i) wins over the early stop, which stays visible.
  const SimResult q = simulate(test::single_sphere(), SimParams{});
  EXPECT_EQ(q.outcome, Outcome::RollingContact);
  EXPECT_TRUE(q.stopped_early);
  EXPECT_DOUBLE_EQ(q.ground_contact_fraction[0], 1.0);
  EXPECT_EQ(q.d, 0.0);
}

TEST(Simulation, AStableRigidClusterStopsEarly) {
  const SimResult r = simulate(test::rigid_row(), no_rolling_rules());
  EXPECT_EQ(r.outcome, Outcome::StoppedEarly);
  EXPECT_LT(r.steps_run, 300);
  EXPECT_NEAR(r.d, 0.0, 1e-3);
}

TEST(Simulation, AMovingControllerPreventsTheEarlyStop) {
  // The flipper sled moves all the time: it runs every step.
  SimParams p;
  p.steps = 300;
  const SimResult r = simulate(test::flipper_sled(), p);
  EXPECT_FALSE(r.stopped_early);
  EXPECT_EQ(r.steps_run, 300);
}

TEST(Simulation, AViolentServoTripsTheAccelerationFault) {
  SimParams p;
  p.motor_strength = 1e6;
  p.servo_gain = 1e4;
  p.servo_max_speed = 1e4;
  const Robot robot = test::flipper_sled(3.0, 2.0);
  const SimResult r = simulate(robot, p);
  EXPECT_EQ(r.outcome, Outcome::AccelFault);
  EXPECT_LT(r.steps_run, 50);
  EXPECT_EQ(r.d, 0.0);
  EXPECT_EQ(r.d_final, r.d_init);
  EXPECT_GT(std::max(r.max_linear_acceleration / p.max_linear_acceleration,
                     r.max_angular_acceleration / p.max_angular_acceleration),
            1.0);
  // The same robot with the default servo runs without a fault.
  SimParams q;
  q.steps = 500;
  EXPECT_NE(simulate(robot, q).outcome, Outcome::AccelFault);
}

TEST(Simulation, ARollingSphereTripsTheSpinRule) {
  // A sphere of radius 0.2 rolling towards +x at 0.3 m/s: omega_y = v / r = 1.5 rad/s,
  // over the default threshold; in 25 s it rolls 7.5 m (the target is 10 m away).
  SimParams p;
  p.rolling_contact_rule = false;
  ASSERT_LT(p.rolling_spin_threshold, 1.4);
  Simulation sim(test::single_sphere(0.2), p);
  sim.set_body_velocity(0, {0.3, 0, 0}, {0, 1.5, 0});
  while (sim.step()) {
  }
  const SimResult r = sim.result();
  EXPECT_EQ(r.outcome, Outcome::RollingSpin);
  EXPECT_EQ(r.steps_run, p.steps);
  EXPECT_GT(r.mean_angular_speed[0], 1.4);
  EXPECT_GT(r.d_raw, 6.0);  // it did roll towards the target ...
  EXPECT_EQ(r.d, 0.0);      // ... and scores nothing for it
  // With both rules on, rule (i) (it touched the ground all the time) comes first.
  Simulation both(test::single_sphere(0.2), SimParams{});
  both.set_body_velocity(0, {0.3, 0, 0}, {0, 1.5, 0});
  while (both.step()) {
  }
  EXPECT_EQ(both.result().outcome, Outcome::RollingContact);
  EXPECT_THROW(both.set_body_velocity(0, {0, 0, 0}, {0, 0, 0}), std::logic_error);
}

TEST(Simulation, AFlipperDragsTheSledTowardsTheTarget) {
  // Default parameters and rules: no rolling rule fires, the sled gains ground.
  const SimResult r = simulate(test::flipper_sled(), SimParams{});
  EXPECT_EQ(r.outcome, Outcome::Completed);
  EXPECT_GT(r.d, 1.0);
  EXPECT_DOUBLE_EQ(r.d, r.d_raw);
  EXPECT_NEAR(r.d, r.d_init - r.d_final, 1e-12);
  for (double f : r.ground_contact_fraction) EXPECT_LE(f, 0.95);
  for (double w : r.mean_angular_speed) EXPECT_LE(w, SimParams{}.rolling_spin_threshold);
  // With its drive switched off (weight 0, bias 0) the sled stays put.
  const SimResult off = simulate(test::flipper_sled(0.0), no_rolling_rules());
  EXPECT_LT(std::abs(off.d_raw), 0.05);
}

TEST(Simulation, StateDescribesBodiesSpheresNeuronsAndSensors) {
  const Robot robot = test::flipper_sled();
  Simulation sim(robot, SimParams{});
  const SimState& s0 = sim.state();
  EXPECT_EQ(s0.step, 0);
  ASSERT_EQ(s0.body_position.size(), 2u);
  ASSERT_EQ(s0.sphere_center.size(), 4u);
  ASSERT_EQ(s0.neuron_output.size(), 1u);
  ASSERT_EQ(s0.sensor_value.size(), 2u);
  ASSERT_EQ(s0.sphere_touching.size(), 4u);
  for (size_t i = 0; i < 4; ++i) EXPECT_NEAR((s0.sphere_center[i] - robot.spheres[i].center).norm(), 0, 1e-14);
  EXPECT_EQ(s0.body_quaternion[0], Eigen::Vector4d(1, 0, 0, 0));
  for (int i = 0; i < 100; ++i) ASSERT_TRUE(sim.step());
  const SimState& s = sim.state();
  EXPECT_EQ(s.step, 100);
  EXPECT_NEAR(s.time, 1.0, 1e-12);
  for (const auto& q : s.body_quaternion) EXPECT_NEAR(q.norm(), 1.0, 1e-9);
  // Body 0's spheres 0 and 1 stay 0.3 apart (rigid), as do body 1's spheres 2 and 3.
  EXPECT_NEAR((s.sphere_center[0] - s.sphere_center[1]).norm(), 0.3, 1e-9);
  EXPECT_NEAR((s.sphere_center[2] - s.sphere_center[3]).norm(), 0.3, 1e-9);
  for (double o : s.neuron_output) EXPECT_LT(std::abs(o), 1.0);
}

TEST(Simulation, StepReportsWhetherItSteppedAndStopsAtTheEnd) {
  SimParams p = no_rolling_rules();  // 0.3 s is too short a time for averaging spins
  p.steps = 30;
  Simulation sim(test::flipper_sled(), p);
  int n = 0;
  while (sim.step()) ++n;
  EXPECT_EQ(n, 30);
  EXPECT_TRUE(sim.done());
  EXPECT_FALSE(sim.step());
  EXPECT_EQ(sim.state().step, 30);
  EXPECT_EQ(sim.result().steps_run, 30);
  EXPECT_EQ(sim.result().outcome, Outcome::Completed);
}

TEST(Simulation, TimingAccumulatesOnlyWhenEnabled) {
  SimParams p;
  p.steps = 20;
  Simulation sim(test::flipper_sled(), p);
  sim.step();
  EXPECT_EQ(sim.timing().physics, 0.0);
  sim.enable_timing(true);
  while (sim.step()) {
  }
  EXPECT_GT(sim.timing().physics, 0.0);
}

TEST(Simulation, RejectsBadModelsAndParameters) {
  Robot bad = test::flipper_sled();
  bad.joints[0].axis = {0, 0, 0};
  EXPECT_THROW(Simulation(bad, SimParams{}), std::invalid_argument);
  SimParams p;
  p.dt = 0;
  EXPECT_THROW(Simulation(test::flipper_sled(), p), std::invalid_argument);
  p = SimParams{};
  p.distance_sensor_range = 0;
  EXPECT_THROW(Simulation(test::flipper_sled(), p), std::invalid_argument);
  Simulation ok(test::flipper_sled(), SimParams{});
  EXPECT_THROW(ok.set_body_velocity(2, {0, 0, 0}, {0, 0, 0}), std::invalid_argument);
}

}  // namespace
}  // namespace robozoo
