#include "evolve/sim/episode/episode_rules.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace robozoo {
namespace {

// 100 steps, 2 spheres, 2 bodies; sphere 0 on the ground for `ground0` steps,
// body 1 spinning at `spin` rad/s about z on average.
EpisodeRecord record(int ground0, double spin, bool fault = false, bool early = false) {
  EpisodeRecord r(2, 2);
  r.steps_run = 100;
  r.ground_steps = {ground0, 10};
  r.angular_velocity_sum[1] = Eigen::Vector3d(0, 0, spin * 100);
  r.fault = fault;
  r.stopped_early = early;
  r.max_linear_acceleration = 12;
  return r;
}

TEST(Rules, ValidRunsScoreTheDisplacement) {
  const SimParams p;
  const SimResult r = apply_rules(record(50, 0.1), 9.0, 7.5, p);
  EXPECT_EQ(r.outcome, Outcome::Completed);
  EXPECT_DOUBLE_EQ(r.d, 1.5);
  EXPECT_DOUBLE_EQ(r.d_raw, 1.5);
  EXPECT_DOUBLE_EQ(r.d_final, 7.5);
  EXPECT_DOUBLE_EQ(r.ground_contact_fraction[0], 0.5);
  EXPECT_DOUBLE_EQ(r.ground_contact_fraction[1], 0.1);
  EXPECT_NEAR(r.mean_angular_speed[1], 0.1, 1e-15);
  EXPECT_DOUBLE_EQ(r.mean_angular_speed[0], 0.0);
  EXPECT_DOUBLE_EQ(r.max_linear_acceleration, 12);
  EXPECT_EQ(apply_rules(record(50, 0.1, false, true), 9.0, 9.5, p).outcome, Outcome::StoppedEarly);
  EXPECT_DOUBLE_EQ(apply_rules(record(50, 0.1, false, true), 9.0, 9.5, p).d, -0.5);  // d may be negative
}

TEST(Rules, PrecedenceIsFaultThenContactThenSpin) {
  const SimParams p;  // fraction 0.95, threshold from SimParams
  const double spin = 2 * p.rolling_spin_threshold;
  const auto outcome = [&](const EpisodeRecord& r) { return apply_rules(r, 9.0, 7.0, p).outcome; };
  EXPECT_EQ(outcome(record(100, spin, true)), Outcome::AccelFault);
  EXPECT_EQ(outcome(record(100, spin)), Outcome::RollingContact);
  EXPECT_EQ(outcome(record(96, 0.0)), Outcome::RollingContact);
  EXPECT_EQ(outcome(record(95, 0.0)), Outcome::Completed);  // "more than 95 %"
  EXPECT_EQ(outcome(record(50, spin)), Outcome::RollingSpin);
  EXPECT_EQ(outcome(record(50, spin, false, true)), Outcome::RollingSpin);
  for (const auto& rec : {record(100, 0, true), record(100, 0), record(0, spin)}) {
    const SimResult r = apply_rules(rec, 9.0, 7.0, p);
    EXPECT_DOUBLE_EQ(r.d, 0.0);
    EXPECT_DOUBLE_EQ(r.d_final, 9.0);  // = d_init when invalidated
    EXPECT_DOUBLE_EQ(r.d_raw, 2.0);    // what the robot did, kept for statistics
  }
}

TEST(Rules, RulesCanBeSwitchedOff) {
  SimParams p;
  p.rolling_contact_rule = false;
  const double spin = 2 * p.rolling_spin_threshold;
  EXPECT_EQ(apply_rules(record(100, spin), 9, 8, p).outcome, Outcome::RollingSpin);
  p.rolling_spin_rule = false;
  EXPECT_EQ(apply_rules(record(100, spin), 9, 8, p).outcome, Outcome::Completed);
  EXPECT_EQ(apply_rules(record(100, spin, true), 9, 8, p).outcome, Outcome::AccelFault);
}

TEST(Rules, AccelerationFaultIncludesNonFiniteValues) {
  SimParams p;
  p.max_linear_acceleration = 100;
  p.max_angular_acceleration = 1000;
  EXPECT_FALSE(acceleration_fault(100, 1000, p));
  EXPECT_TRUE(acceleration_fault(100.5, 0, p));
  EXPECT_TRUE(acceleration_fault(0, 1000.5, p));
  EXPECT_TRUE(acceleration_fault(std::nan(""), 0, p));
  EXPECT_TRUE(acceleration_fault(0, std::numeric_limits<double>::infinity(), p));
}

TEST(Rules, RestNeedsStillBodiesAndASettledController) {
  SimParams p;
  p.rest_linear_speed = 0.01;
  p.rest_angular_speed = 0.02;
  p.rest_output_rate = 0.1;  // per second: 0.001 per step of 0.01 s
  const std::vector<Eigen::Vector3d> slow{{0.005, 0, 0}}, spin{{0, 0, 0.03}}, still{{0, 0, 0}};
  EXPECT_TRUE(at_rest(slow, still, {0.0005}, p));
  EXPECT_FALSE(at_rest({{0.02, 0, 0}}, still, {}, p));
  EXPECT_FALSE(at_rest(slow, spin, {}, p));
  EXPECT_FALSE(at_rest(slow, still, {0.002}, p));
  EXPECT_TRUE(at_rest(slow, still, {}, p));
}

}  // namespace
}  // namespace robozoo
