#include "evolve/sim/robots/random_robot.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "evolve/sim/setup/robot_check.hpp"

namespace robozoo {
namespace {

TEST(RandomRobot, ObeysTheModelsConventionsAndGrowthsPlacementRules) {
  Rng rng(11);
  RandomRobotParams p;
  int jointed_robots = 0, many_spheres = 0;
  for (int k = 0; k < 60; ++k) {
    const Robot r = random_robot(rng, p);
    ASSERT_NO_THROW(check_robot(r));
    const int n = static_cast<int>(r.spheres.size());
    ASSERT_GE(n, 1);
    ASSERT_LE(n, 50);
    many_spheres += n >= 25;
    jointed_robots += !r.joints.empty();
    double rmax = 0;
    for (const Sphere& s : r.spheres) rmax = std::max(rmax, s.radius);
    for (const Sphere& s : r.spheres) {
      EXPECT_GE(s.radius, p.r_min - 1e-12);
      EXPECT_LE(s.radius, p.r_max + 1e-12);
      EXPECT_DOUBLE_EQ(s.center.z(), rmax);  // one plane, largest sphere on the ground
      EXPECT_LE(std::abs(s.center.x()), p.bound + 1e-12);
      if (s.parent >= 0) {  // centre on the parent's circle: parent and child touch
        const Sphere& q = r.spheres[s.parent];
        EXPECT_NEAR((s.center - q.center).norm(), q.radius, 1e-12);
      }
      if (s.has_joint) {
        EXPECT_GT(s.num_children, 0);  // leaf joints are pruned
        const Eigen::Vector3d dir = (s.center - r.spheres[s.parent].center).normalized();
        EXPECT_NEAR(dir.dot(s.joint_axis), 0.0, 1e-12);
        EXPECT_GT(s.joint_range, 0.0);
        EXPECT_LE(s.joint_range, p.max_joint_range);
      }
    }
  }
  EXPECT_GT(jointed_robots, 20);
  EXPECT_GT(many_spheres, 10);
}

TEST(RandomRobot, IsAPureFunctionOfTheGeneratorState) {
  Rng a(5), b(5);
  for (int k = 0; k < 5; ++k) {
    const Robot x = random_robot(a, {}), y = random_robot(b, {});
    ASSERT_EQ(x.spheres.size(), y.spheres.size());
    for (size_t i = 0; i < x.spheres.size(); ++i) EXPECT_EQ(x.spheres[i].center, y.spheres[i].center);
    EXPECT_EQ(x.w_neuron_neuron, y.w_neuron_neuron);
  }
}

TEST(RandomRobot, HonoursAnExactSphereCount) {
  Rng rng(2);
  RandomRobotParams p;
  p.min_spheres = p.max_spheres = 10;
  for (int k = 0; k < 10; ++k) EXPECT_EQ(random_robot(rng, p).spheres.size(), 10u);
  p.min_spheres = 0;
  EXPECT_THROW(random_robot(rng, p), std::invalid_argument);
}

}  // namespace
}  // namespace robozoo
