#include "evolve/sim/step/servo.hpp"

#include <gtest/gtest.h>

#include "evolve/sim/robots/robot_builder.hpp"

namespace robozoo {
namespace {

TEST(Servo, SpeedIsGainTimesErrorCapped) {
  SimParams p;
  p.servo_gain = 10.0;
  p.servo_max_speed = 3.0;
  EXPECT_DOUBLE_EQ(servo_speed(0.25, 0.2, p), 10.0 * (0.25 - 0.2));
  EXPECT_DOUBLE_EQ(servo_speed(1.0, 0.0, p), 3.0);
  EXPECT_DOUBLE_EQ(servo_speed(-1.0, 0.5, p), -3.0);
  EXPECT_DOUBLE_EQ(servo_speed(0.3, 0.3, p), 0.0);
}

TEST(Servo, TorqueLimitScalesWithTheLighterBodysMoment) {
  // Body 0: root r 0.2 at origin. Body 1 (jointed at (0.2,0,0)): sphere 1 r 0.1 and
  // sphere 2 r 0.1 at (0.3,0,0). Anchor = sphere 1's centre.
  RobotBuilder b;
  const int a = b.add_root({0, 0, 0}, 0.2);
  const int j = b.add_jointed(a, {0.2, 0, 0}, 0.1, {0, 1, 0}, 0.5);
  b.add_fused(j, {0.3, 0, 0}, 0.1);
  const Robot r = b.build();
  const double m_root = sphere_mass(r.spheres[0]), m_small = sphere_mass(r.spheres[1]);
  const double parent_body = m_root * 0.2;
  // Sphere 1 sits on the anchor: its lever is its radius, 0.1; sphere 2 is 0.1 away.
  const double child_body = m_small * 0.1 + m_small * 0.1;
  ASSERT_LT(child_body, parent_body);
  const auto moments = joint_body_moments(r);
  ASSERT_EQ(moments.size(), 1u);
  EXPECT_NEAR(moments[0], child_body, 1e-15);
  SimParams p;
  p.motor_strength = 4.0;
  p.gravity = 9.0;
  EXPECT_NEAR(motor_torque_limits(r, p)[0], 36.0 * moments[0], 1e-15);
}

TEST(Servo, OnlyTheTwoHingedBodiesCount) {
  // Chain of bodies 0 - 1 - 2 (spheres 0 | 1 | 2, 3): joint 0 joins bodies 0 and 1
  // only, whatever hangs beyond body 1.
  RobotBuilder b;
  const int a = b.add_root({0, 0, 0}, 0.5);
  const int j1 = b.add_jointed(a, {0.5, 0, 0}, 0.1, {0, 1, 0}, 0.5);
  const int j2 = b.add_jointed(j1, {0.6, 0, 0}, 0.1, {0, 1, 0}, 0.5);
  b.add_fused(j2, {0.7, 0, 0}, 0.1);
  const Robot r = b.build();
  const double m = sphere_mass(r.spheres[1]);  // all small spheres are equal
  const auto moments = joint_body_moments(r);
  ASSERT_EQ(moments.size(), 2u);
  EXPECT_NEAR(moments[0], m * 0.1, 1e-15);  // body 1: sphere 1 on the anchor (0.5,0,0)
  EXPECT_NEAR(moments[1], m * 0.1, 1e-15);  // min(body 1: 0.1 away, body 2: levers 0.1 + 0.1)
}

}  // namespace
}  // namespace robozoo
