#include "evolve/sim/step/sensors.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Geometry>

#include "evolve/sim/robots/robot_builder.hpp"
#include "evolve/sim/episode/simulation.hpp"

namespace robozoo {
namespace {

TEST(Sensors, DistanceIsOneMinusDistanceOverRangeClamped) {
  SimParams p;  // target (50, 0, 0), range 100
  EXPECT_DOUBLE_EQ(distance_sensor_value({0, 0, 0}, p), 0.5);
  EXPECT_DOUBLE_EQ(distance_sensor_value({50, 0, 0}, p), 1.0);
  EXPECT_DOUBLE_EQ(distance_sensor_value({50, 3, 4}, p), 1.0 - 5.0 / 100.0);
  EXPECT_DOUBLE_EQ(distance_sensor_value({-75, 0, 0}, p), 0.0);
  p.target_x = 10;
  p.distance_sensor_range = 20;
  EXPECT_DOUBLE_EQ(distance_sensor_value({10, 3, 4}, p), 1.0 - 5.0 / 20.0);
  EXPECT_DOUBLE_EQ(distance_sensor_value({-15, 0, 0}, p), 0.0);
  p.distance_sensor_range = 40;
  EXPECT_DOUBLE_EQ(distance_sensor_value({-15, 0, 0}, p), 1.0 - 25.0 / 40.0);
}

TEST(Sensors, TimeIsASineOfFrequencyF) {
  SimParams p;
  p.time_sensor_frequency = 2.0;
  EXPECT_DOUBLE_EQ(time_sensor_value(0.0, p), 0.0);
  EXPECT_NEAR(time_sensor_value(0.125, p), 1.0, 1e-15);
  EXPECT_NEAR(time_sensor_value(0.0625, p), std::sqrt(0.5), 1e-15);
}

TEST(Sensors, DistanceSensorReadsItsSpheresWorldCentre) {
  // Root at the origin, r 0.2, distance sensor on the second sphere at (0.2, 0.3, 0).
  RobotBuilder b;
  const int a = b.add_root({0, 0, 0}, 0.2);
  b.add_fused(a, {0.2, 0.3, 0}, 0.2, 1.0, kSensorDistance);
  const Robot r = b.build();
  Simulation sim(r, SimParams{});
  const double d = (Eigen::Vector3d(0.2, 0.3, 0.2) - Eigen::Vector3d(50, 0, 0)).norm();
  ASSERT_EQ(sim.state().sensor_value.size(), 1u);
  EXPECT_NEAR(sim.state().sensor_value[0], 1.0 - d / 100.0, 1e-14);
}

TEST(Sensors, TimeSensorFollowsSimulatedTime) {
  RobotBuilder b;
  b.add_root({0, 0, 0}, 0.2, 1.0, kSensorTime);
  const Robot r = b.build();
  SimParams p;
  p.time_sensor_frequency = 0.5;
  Simulation sim(r, p);
  EXPECT_DOUBLE_EQ(sim.state().sensor_value[0], 0.0);
  for (int i = 0; i < 37; ++i) sim.step();
  EXPECT_NEAR(sim.state().time, 0.37, 1e-15);
  EXPECT_NEAR(sim.state().sensor_value[0], std::sin(2 * M_PI * 0.5 * 0.37), 1e-12);
}

TEST(Sensors, TouchIsOneOnTheGroundAndZeroInTheAir) {
  // Two separate robots: one resting, one dropped from 0.5 m above the ground.
  RobotBuilder rest, drop;
  rest.add_root({0, 0, 0}, 0.2, 1.0, kSensorTouch);
  drop.add_root({0, 0, 0.7}, 0.2, 1.0, kSensorTouch);
  SimParams p;
  p.rest_steps = 10000;  // no early stop
  Simulation on_ground(rest.build(), p), in_air(drop.build(false), p);
  EXPECT_EQ(on_ground.state().sensor_value[0], 1.0);
  EXPECT_EQ(in_air.state().sensor_value[0], 0.0);
  // A fall of 0.5 m takes sqrt(2 * 0.5 / 9.81) = 0.32 s.
  for (int i = 0; i < 20; ++i) {
    on_ground.step();
    in_air.step();
  }
  EXPECT_EQ(on_ground.state().sensor_value[0], 1.0);
  EXPECT_EQ(in_air.state().sensor_value[0], 0.0);
  for (int i = 0; i < 30; ++i) in_air.step();
  EXPECT_EQ(in_air.state().sensor_value[0], 1.0);
  EXPECT_EQ(in_air.state().sphere_touching[0], 1);
}

TEST(Sensors, ProprioceptionIsTheHingeAngleOverItsRange) {
  // A flipper swinging about the vertical axis, clear of the ground; its neuron's
  // bias holds the target at tanh(1) of the range, which the servo reaches.
  RobotBuilder b;
  const int a = b.add_root({0, 0, 0}, 0.3);
  const int j = b.add_jointed(a, {0.3, 0, 0}, 0.1, {0, 0, 1}, 0.5, 0.5, 1.0, 1.0, kSensorProprio);
  b.add_fused(j, {0.4, 0, 0}, 0.1);
  const Robot r = b.build();
  SimParams p;
  p.rest_steps = 10000;
  Simulation sim(r, p);
  EXPECT_DOUBLE_EQ(sim.state().sensor_value[0], 0.0);
  for (int i = 0; i < 200; ++i) sim.step();
  EXPECT_NEAR(sim.state().sensor_value[0], std::tanh(1.0), 0.02);
  // The bodies' relative rotation is 0.5 * tanh(1) rad about the hinge axis.
  const auto quat = [&](int b) {
    const Eigen::Vector4d& q = sim.state().body_quaternion[b];
    return Eigen::Quaterniond(q[0], q[1], q[2], q[3]);
  };
  const Eigen::AngleAxisd rel(quat(0).conjugate() * quat(1));
  EXPECT_NEAR(rel.angle(), 0.5 * std::tanh(1.0), 0.02);
  EXPECT_NEAR(std::abs(rel.axis().z()), 1.0, 1e-6);
}

}  // namespace
}  // namespace robozoo
