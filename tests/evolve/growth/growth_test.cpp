// grow() on hand-built CPPNs whose outputs are known constants (or simple
// functions of x and r_parent), so the morphology can be worked out by hand from
// the rules of docs/method.md section 2; and determinism.
#include "evolve/growth/growth.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "evolve/core/rng.hpp"
#include "evolve/cppn/random_genome.hpp"
#include "evolve/growth/robot_hash.hpp"
#include "tests/evolve/growth/cppn_builders.hpp"

namespace robozoo {
namespace {

using testing::bare_robot_genome;
using testing::constant;
using testing::inv_ssig;
using testing::link;
using testing::ssig;

Robot grow_genome(const Genome& g, const GrowthParams& p = testing::unit_bias_growth()) {
  Network net(g, robot_layout());
  return grow(net, p);
}

double density_at(double m, const GrowthParams& p) {
  return p.rho_min + (p.rho_max - p.rho_min) * (m - p.t_matter) / (1 - p.t_matter);
}

TEST(Grow, NoMatterAnywhereLeavesTheRootAlone) {
  Genome g = bare_robot_genome();
  constant(g, kOutMatter, -0.5);
  const Robot r = grow_genome(g);
  ASSERT_EQ(r.spheres.size(), 1u);
  EXPECT_EQ(r.spheres[0].parent, -1);
  EXPECT_EQ(r.spheres[0].radius, 0.1);
  EXPECT_EQ(r.spheres[0].density, testing::unit_bias_growth().rho_min);  // m <= T: the root gets rho_min
  EXPECT_EQ(r.num_bodies, 1);
  EXPECT_TRUE(r.joints.empty());
  EXPECT_TRUE(r.sensors.empty());
  EXPECT_EQ(r.r_term, 1.0);
  EXPECT_FALSE(r.simulate);
  // Resting on the ground: centre at its radius.
  EXPECT_EQ(r.spheres[0].center, Eigen::Vector3d(0, 0, 0.1));
  EXPECT_EQ(r.vertical_shift, 0.1);
}

TEST(Grow, RootWithSensorsScoresTwoButNeverProprioception) {
  Genome g = bare_robot_genome();
  constant(g, kOutMatter, -0.5);
  for (int s = kOutSensorDistance; s <= kOutSensorTime; ++s) constant(g, s, 0.9);
  const Robot r = grow_genome(g);
  ASSERT_EQ(r.spheres.size(), 1u);
  // Proprioception needs a joint, and the root has none.
  ASSERT_EQ(r.sensors.size(), 3u);
  EXPECT_EQ(r.sensors[0].type, SensorType::Distance);
  EXPECT_EQ(r.sensors[1].type, SensorType::Touch);
  EXPECT_EQ(r.sensors[2].type, SensorType::Time);
  EXPECT_EQ(r.spheres[0].sensors, kSensorDistance | kSensorTouch | kSensorTime);
  EXPECT_EQ(r.r_term, 2.0);  // 1 + sensors; no joint, so no neuron and no link
  EXPECT_FALSE(r.simulate);
}

// m = ssig(40 r_parent - 1): 0.905 around the root (r_parent = 0.1), 0.462 < T
// around a sphere of radius 0.05; r_scale = -0.6, so children get
// clamp(0.1 * 0.4) = r_min = 0.05 and bear no matter around themselves.
Genome ring_genome() {
  Genome g = bare_robot_genome();
  link(g, kInRParent, kOutMatter, 40.0);
  link(g, kInBias, kOutMatter, -1.0);
  constant(g, kOutRadius, -0.6);
  return g;
}

// Rigid ring: all spheres fuse into one component, so only rule (b) spaces them:
// centres on the root's circle (radius 0.1) at least r = 0.05 apart, i.e. a chord
// 2 * 0.1 * sin(dphi / 2) >= 0.05, dphi >= 2 asin(0.25) = 0.5054 rad. Every point
// has the same m, so points are visited in cloud order k = 0, 1, ...: the first
// is k = 0, and each next one 51 steps (0.51 rad; 50 steps = 0.50 rad is too
// close) after the last: k = 0, 51, ..., 561. The next, 612, lies only
// 2 pi - 6.12 = 0.163 rad from k = 0 (and 562..628 are all too close to 561 or
// to 0), so the ring has 12 children.
TEST(Grow, MatterEverywhereWithoutJointsGrowsARigidRing) {
  const GrowthParams p = testing::unit_bias_growth();
  const Robot r = grow_genome(ring_genome(), p);
  ASSERT_EQ(r.spheres.size(), 13u);
  const double m = ssig(40 * 0.1 - 1);
  for (int i = 1; i <= 12; ++i) {
    const Sphere& s = r.spheres[i];
    EXPECT_EQ(s.parent, 0);
    EXPECT_EQ(s.cloud_angle_index, 51 * (i - 1));
    EXPECT_EQ(s.radius, 0.05);
    EXPECT_FALSE(s.has_joint);
    EXPECT_FALSE(s.joint_pruned);
    EXPECT_EQ(s.body, 0);
    EXPECT_NEAR(s.matter, m, 1e-15);
    EXPECT_NEAR(s.density, density_at(m, p), 1e-12);
    const double phi = 0.51 * (i - 1);
    EXPECT_NEAR(s.center.x(), 0.1 * std::cos(phi), 1e-12);
    EXPECT_NEAR(s.center.y(), 0.1 * std::sin(phi), 1e-12);
    EXPECT_EQ(s.center.z(), 0.1);  // the root (0.1) is the largest sphere
  }
  EXPECT_EQ(r.spheres[0].num_children, 12);
  EXPECT_EQ(r.num_bodies, 1);
  EXPECT_TRUE(r.joints.empty());
  EXPECT_TRUE(r.neurons.empty());
  EXPECT_EQ(r.r_term, 1.0);
}

// Jointed ring: every child starts its own component, joined to the root's only,
// so siblings may not interpenetrate (rule (c)): chord >= 0.05 + 0.05, dphi >=
// 2 asin(0.5) = pi / 3 = 1.0472 rad, 105 steps: k = 0, 105, 210, 315, 420; then
// 525 lies 2 pi - 5.25 = 1.033 rad from k = 0. Five children, all leaves, so
// pruning makes every joint rigid and drops the proprioceptive sensors.
TEST(Grow, JointsEverywhereOnLeavesArePrunedAway) {
  Genome g = ring_genome();
  constant(g, kOutJoint, 0.9);
  constant(g, kOutSensorProprio, 0.9);
  constant(g, kOutSensorTouch, 0.9);
  const Robot r = grow_genome(g);
  ASSERT_EQ(r.spheres.size(), 6u);
  for (int i = 1; i <= 5; ++i) {
    const Sphere& s = r.spheres[i];
    EXPECT_EQ(s.cloud_angle_index, 105 * (i - 1));
    EXPECT_EQ(s.num_children, 0);
    EXPECT_FALSE(s.has_joint);
    EXPECT_TRUE(s.joint_pruned);
    EXPECT_EQ(s.motor_neuron, -1);
    EXPECT_EQ(s.joint_axis, Eigen::Vector3d::Zero());
    EXPECT_EQ(s.body, 0);  // merged into the root's body
    EXPECT_EQ(s.sensors, kSensorTouch);
  }
  EXPECT_EQ(r.num_bodies, 1);
  EXPECT_TRUE(r.joints.empty());
  EXPECT_TRUE(r.neurons.empty());
  EXPECT_EQ(r.sensors.size(), 6u);  // touch everywhere, proprioception nowhere
  EXPECT_EQ(r.r_term, 2.0);
}

TEST(Grow, BoundingSquareCanExcludeEveryCloudPoint) {
  // Every point of the root's cloud has max(|x|, |y|) >= 0.1 / sqrt(2) = 0.0707.
  Genome g = bare_robot_genome();
  constant(g, kOutMatter, 0.9);
  GrowthParams p = testing::unit_bias_growth();
  p.bound = 0.07;
  EXPECT_EQ(grow_genome(g, p).spheres.size(), 1u);
  p.bound = 0.075;
  EXPECT_GT(grow_genome(g, p).spheres.size(), 1u);
}

// A chain along +x: m = ssig(20 x + 0.75) > T iff x > 0.0492; r_scale = -0.3
// (s = 0.7); joints everywhere; max_spheres = 3.
// - Root cloud: k = 0, (0.1, 0), has the largest x and becomes sphere 1, radius
//   0.07, jointed. Any other root point with m > T has |phi| < 1.06 rad, but as a
//   jointed sphere of radius 0.07 it must clear sphere 1 (another component) by
//   0.14: chord 0.2 sin(dphi / 2) >= 0.14 needs dphi >= 1.55. So one child.
// - Sphere 1's cloud (radius 0.07 around (0.1, 0)): k = 0, (0.17, 0), radius
//   clamp(0.049) = 0.05, jointed; it clears the root (not directly joined to its
//   component) since 0.17 >= 0.1 + 0.05. Third sphere: growth stops.
// Sphere 2 is a leaf, so its joint is pruned; sphere 1 keeps its joint.
Genome chain_genome(double w) {
  Genome g = bare_robot_genome();
  link(g, kInX, kOutMatter, 20.0);
  link(g, kInBias, kOutMatter, 0.75);
  constant(g, kOutRadius, -0.3);
  constant(g, kOutJoint, 0.9);
  constant(g, kOutTheta, 0.5);
  constant(g, kOutTau, 0.2);
  constant(g, kOutOmega, -0.4);
  for (int s = kOutSensorDistance; s <= kOutSensorTime; ++s) constant(g, s, 0.9);
  constant(g, kOutWeight, w);
  return g;
}

TEST(Grow, JointSurvivesOnANonLeafSphere) {
  GrowthParams p = testing::unit_bias_growth();
  p.max_spheres = 3;
  const Robot r = grow_genome(chain_genome(0.5), p);
  ASSERT_EQ(r.spheres.size(), 3u);
  const double s = 1 + ssig(inv_ssig(-0.3));
  EXPECT_EQ(r.spheres[1].parent, 0);
  EXPECT_EQ(r.spheres[1].cloud_angle_index, 0);
  EXPECT_DOUBLE_EQ(r.spheres[1].radius, 0.1 * s);
  EXPECT_NEAR(r.spheres[1].center.x(), 0.1, 1e-15);
  EXPECT_EQ(r.spheres[2].parent, 1);
  EXPECT_EQ(r.spheres[2].cloud_angle_index, 0);
  EXPECT_EQ(r.spheres[2].radius, 0.05);
  EXPECT_NEAR(r.spheres[2].center.x(), 0.1 + 0.1 * s, 1e-15);

  // Sphere 1 keeps its joint; leaf sphere 2's joint was pruned into body 1.
  EXPECT_TRUE(r.spheres[1].has_joint);
  EXPECT_FALSE(r.spheres[2].has_joint);
  EXPECT_TRUE(r.spheres[2].joint_pruned);
  EXPECT_EQ(r.num_bodies, 2);
  EXPECT_EQ(r.spheres[0].body, 0);
  EXPECT_EQ(r.spheres[1].body, 1);
  EXPECT_EQ(r.spheres[2].body, 1);
  ASSERT_EQ(r.joints.size(), 1u);
  const Joint& j = r.joints[0];
  EXPECT_EQ(j.sphere, 1);
  EXPECT_EQ(j.parent_body, 0);
  EXPECT_EQ(j.child_body, 1);
  EXPECT_EQ(j.neuron, 0);
  // a = +x, n = a x z = -y, rotated by pi * 0.5 about a: a x n = -z.
  EXPECT_NEAR(j.axis.x(), 0, 1e-12);
  EXPECT_NEAR(j.axis.y(), 0, 1e-12);
  EXPECT_NEAR(j.axis.z(), -1, 1e-12);
  EXPECT_NEAR(j.range, (0.9 - 0.7) / 0.3 * M_PI / 2, 1e-12);
  ASSERT_EQ(r.neurons.size(), 1u);
  EXPECT_EQ(r.neurons[0].sphere, 1);
  EXPECT_NEAR(r.neurons[0].tau, 0.05 + 0.95 * 1.2 / 2, 1e-12);
  EXPECT_NEAR(r.neurons[0].omega, -0.4 * 3.0, 1e-12);
  EXPECT_EQ(r.spheres[1].motor_neuron, 0);

  // Sensors: root D T Time; sphere 1 D T P Time; sphere 2 D T Time (its P went
  // with its joint).
  ASSERT_EQ(r.sensors.size(), 10u);
  const SensorType want[] = {SensorType::Distance, SensorType::Touch,   SensorType::Time, SensorType::Distance,
                             SensorType::Touch,    SensorType::Proprio, SensorType::Time, SensorType::Distance,
                             SensorType::Touch,    SensorType::Time};
  const int sphere_of[] = {0, 0, 0, 1, 1, 1, 1, 2, 2, 2};
  for (int k = 0; k < 10; ++k) {
    EXPECT_EQ(r.sensors[k].type, want[k]) << k;
    EXPECT_EQ(r.sensors[k].sphere, sphere_of[k]) << k;
  }
  // Constant w = 0.5 > 0.2: every link is expressed, rescaled from the threshold:
  // (0.5 - 0.2) / 0.8 * 3 = 1.125.
  ASSERT_EQ(r.w_sensor_neuron.rows(), 10);
  ASSERT_EQ(r.w_sensor_neuron.cols(), 1);
  for (int k = 0; k < 10; ++k) EXPECT_NEAR(r.w_sensor_neuron(k, 0), 1.125, 1e-12);
  ASSERT_EQ(r.w_neuron_neuron.rows(), 1);
  EXPECT_NEAR(r.w_neuron_neuron(0, 0), 1.125, 1e-12);
  EXPECT_EQ(r.r_term, 15.0);
  EXPECT_TRUE(r.simulate);
  // The root (0.1) is the largest sphere.
  for (const Sphere& sp : r.spheres) EXPECT_EQ(sp.center.z(), 0.1);
}

TEST(Grow, WeightsAtOrBelowThresholdExpressNoLink) {
  GrowthParams p = testing::unit_bias_growth();
  p.max_spheres = 3;
  const Robot r = grow_genome(chain_genome(0.15), p);
  ASSERT_EQ(r.joints.size(), 1u);
  EXPECT_EQ(r.w_sensor_neuron, Eigen::MatrixXd::Zero(10, 1));
  EXPECT_EQ(r.w_neuron_neuron, Eigen::MatrixXd::Zero(1, 1));
  EXPECT_EQ(r.r_term, 3.0);  // 1 + sensors + joints
  EXPECT_FALSE(r.simulate);
}

TEST(Grow, DistanceSensorIsNeededForSimulation) {
  GrowthParams p = testing::unit_bias_growth();
  p.max_spheres = 3;
  Genome g = chain_genome(0.5);
  for (auto& l : g.links)
    if (l.to == robot_layout().num_inputs + kOutSensorDistance) l.weight = inv_ssig(0.1);
  const Robot r = grow_genome(g, p);
  EXPECT_EQ(r.sensors.size(), 7u);
  EXPECT_EQ(r.r_term, 5.0);  // all four rewards, but no distance sensor: no +10
  EXPECT_FALSE(r.simulate);
}

// The queue takes the sphere of largest m, not the oldest. m = ssig(20 x + 1),
// rigid, r_scale = 0: every radius 0.1, siblings >= 0.1 apart (dphi >= pi/3).
// Root cloud: m > T for |phi| < 1.195; k = 0 (x = 0.1) first, then k = 105
// (1.05 rad) and k = 523 (2 pi - 5.23 = 1.053 rad); every other candidate is
// within pi/3 of one of them. Sphere 1 (k = 0) has the largest m and casts the
// next cloud; its point k = 0, (0.2, 0), m = ssig(5), clears spheres 2 and 3
// (0.173 away) and becomes sphere 4. Sphere 4's m exceeds every other queued
// sphere's (their x is smaller), so the next cloud to bear children is sphere
// 4's, although spheres 2 and 3 are older. Its first child is (0.3, 0).
TEST(Grow, QueuePopsHighestMatterFirst) {
  Genome g = bare_robot_genome();
  link(g, kInX, kOutMatter, 20.0);
  link(g, kInBias, kOutMatter, 1.0);
  const Robot r = grow_genome(g);
  ASSERT_GT(r.spheres.size(), 5u);
  EXPECT_EQ(r.spheres[0].num_children, 3);
  EXPECT_EQ(r.spheres[1].cloud_angle_index, 0);
  EXPECT_EQ(r.spheres[2].cloud_angle_index, 105);
  EXPECT_EQ(r.spheres[3].cloud_angle_index, 523);
  EXPECT_EQ(r.spheres[4].parent, 1);
  EXPECT_EQ(r.spheres[4].cloud_angle_index, 0);
  EXPECT_NEAR(r.spheres[4].matter, ssig(5.0), 1e-15);
  size_t first = 5;
  while (first < r.spheres.size() && r.spheres[first].parent == 1) ++first;
  ASSERT_LT(first, r.spheres.size());
  EXPECT_EQ(r.spheres[first].parent, 4);
  EXPECT_EQ(r.spheres[first].cloud_angle_index, 0);
  EXPECT_NEAR(r.spheres[first].center.x(), 0.3, 1e-12);
}

TEST(Grow, StopsAtMaxSpheres) {
  Genome g = bare_robot_genome();
  constant(g, kOutMatter, 0.9);
  GrowthParams p = testing::unit_bias_growth();
  for (int n : {1, 2, 7, 50}) {
    p.max_spheres = n;
    EXPECT_EQ(grow_genome(g, p).spheres.size(), static_cast<size_t>(n));
  }
}

TEST(Grow, SameGenomeGrowsTheSameRobot) {
  Rng rng(99);
  int grown = 0;
  for (int i = 0; i < 40; ++i) {
    Genome g = random_cppn(robot_layout(), i % 2 == 1, 3, 6, rng);
    for (auto& l : g.links)
      if (l.from == kInBias && l.to == robot_layout().num_inputs + kOutMatter) l.weight += 2.0;
    Network a(g, robot_layout()), b(g, robot_layout());
    const Robot ra = grow(a, {});
    // Growing another robot in between must not leak state through the network.
    Genome other = random_cppn(robot_layout(), true, 2, 4, rng);
    Network c(other, robot_layout());
    (void)grow(c, {});
    const Robot rb = grow(b, {});
    const Robot rc = grow(a, {});
    EXPECT_EQ(robot_hash(ra), robot_hash(rb)) << i;
    EXPECT_EQ(robot_hash(ra), robot_hash(rc)) << i;
    ASSERT_EQ(ra.spheres.size(), rb.spheres.size());
    for (size_t s = 0; s < ra.spheres.size(); ++s) EXPECT_EQ(ra.spheres[s].center, rb.spheres[s].center);
    EXPECT_EQ(ra.w_sensor_neuron, rb.w_sensor_neuron);
    grown += ra.spheres.size() > 1;
  }
  EXPECT_GT(grown, 5);  // the comparison covered real morphologies
}

TEST(Grow, RejectsBadInput) {
  Genome g = bare_robot_genome();
  Network net(g, robot_layout());
  GrowthParams p = testing::unit_bias_growth();
  p.r_min = 0.2;  // above r_init
  EXPECT_THROW(grow(net, p), std::invalid_argument);
  p = {};
  p.max_spheres = 0;
  EXPECT_THROW(grow(net, p), std::invalid_argument);
  GenomeLayout small;
  small.num_inputs = 3;
  small.bias_input = 2;
  small.num_outputs = 1;
  Genome tiny;
  tiny.nodes = {{0, NodeKind::Input, Activation::Linear, 0.0},
                {1, NodeKind::Input, Activation::Linear, 0.0},
                {2, NodeKind::Bias, Activation::Linear, 0.0},
                {3, NodeKind::Output, Activation::SignedSigmoid, 1.0}};
  Network wrong(tiny, small);
  EXPECT_THROW(grow(wrong, {}), std::invalid_argument);
}

}  // namespace
}  // namespace robozoo
