// grow_body (steps 1-4) before pruning: growth-time components and motors.
#include "evolve/growth/body/grow_body.hpp"

#include <gtest/gtest.h>

#include "evolve/growth/growth.hpp"
#include "tests/evolve/growth/cppn_builders.hpp"

namespace robozoo {
namespace {

// The chain of growth_test.cpp: m = ssig(20 x + 0.75), r_scale = -0.3, joints
// everywhere; three spheres along +x, each hinged to the last.
TEST(GrowBody, JointedSpheresStartComponentsAndCarryMotors) {
  Genome g = testing::bare_robot_genome();
  testing::link(g, kInX, kOutMatter, 20.0);
  testing::link(g, kInBias, kOutMatter, 0.75);
  testing::constant(g, kOutRadius, -0.3);
  testing::constant(g, kOutJoint, 0.9);
  testing::constant(g, kOutTau, -1.0 + 1e-9);
  testing::constant(g, kOutOmega, 0.5);
  testing::constant(g, kOutSensorProprio, 0.8);
  Network net(g, robot_layout());
  CppnProbe probe(net, 1.0);
  GrowthParams p;
  p.max_spheres = 3;
  const GrownBody b = grow_body(probe, p);
  ASSERT_EQ(b.spheres.size(), 3u);
  ASSERT_EQ(b.motors.size(), 3u);
  EXPECT_EQ(b.num_components, 3);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(b.spheres[i].body, i);          // each hinge starts a component
    EXPECT_EQ(b.spheres[i].center.z(), 0.0);  // growth frame
    EXPECT_EQ(b.spheres[i].motor_neuron, -1);
  }
  // Before pruning the leaf still has its joint and proprioception.
  for (int i : {1, 2}) {
    EXPECT_TRUE(b.spheres[i].has_joint);
    EXPECT_EQ(b.spheres[i].sensors, kSensorProprio);
    EXPECT_NEAR(b.motors[i].tau, p.tau_min, 1e-8);
    EXPECT_NEAR(b.motors[i].omega, 1.5, 1e-12);
    EXPECT_EQ(b.motors[i].sphere, i);
  }
  EXPECT_EQ(b.spheres[0].num_children, 1);
  EXPECT_EQ(b.spheres[1].num_children, 1);
  EXPECT_EQ(b.spheres[2].num_children, 0);
  // The root's own query, the root's cloud (629 points, all admissible), and sphere
  // 1's cloud less the points no sphere could take: sphere 1 (r = 0.07) sits at
  // (0.1, 0, 0), and its cloud point at angle t lies closer than r_min = 0.05 to the
  // root's centre, rule (b), where 0.0149 + 0.014 cos t < 0.0025, that is
  // |t - pi| < acos(0.885714) = 0.48445 rad: the 97 points k = 266..362.
  EXPECT_EQ(probe.count(), 1 + 629 + (629 - 97));
}

}  // namespace
}  // namespace robozoo
