#include "evolve/growth/finish/vertical_shift.hpp"

#include <gtest/gtest.h>

namespace robozoo {
namespace {

Robot three(double r0, double r1, double r2) {
  Robot r;
  const double radii[] = {r0, r1, r2};
  for (int i = 0; i < 3; ++i) {
    Sphere s;
    s.index = i;
    s.radius = radii[i];
    s.center = Eigen::Vector3d(0.1 * i, -0.2 * i, 0.0);
    r.spheres.push_back(s);
  }
  return r;
}

TEST(VerticalShift, LargestSphereRestsOnTheGround) {
  Robot r = three(0.1, 0.3, 0.2);
  EXPECT_EQ(rest_on_ground(r), 0.3);
  EXPECT_EQ(r.vertical_shift, 0.3);
  for (const Sphere& s : r.spheres) {
    EXPECT_EQ(s.center.z(), 0.3);
    EXPECT_GE(s.center.z() - s.radius, 0.0);
  }
  EXPECT_EQ(r.spheres[1].center.z() - r.spheres[1].radius, 0.0);
  EXPECT_EQ(r.spheres[2].center.x(), 0.2);  // horizontal positions kept
  EXPECT_EQ(r.spheres[2].center.y(), -0.4);
}

TEST(VerticalShift, TiesGoToTheFirstInGrowthOrder) {
  Robot r = three(0.2, 0.4, 0.4);
  r.spheres[1].center.z() = 0.0;
  r.spheres[2].center.z() = 1.0;  // not a growth output, but shows which one is used
  EXPECT_EQ(rest_on_ground(r), 0.4);
  EXPECT_EQ(r.spheres[1].center.z(), 0.4);
}

TEST(VerticalShift, EmptyRobotIsLeftAlone) {
  Robot r;
  EXPECT_EQ(rest_on_ground(r), 0.0);
  EXPECT_EQ(r.vertical_shift, 0.0);
}

}  // namespace
}  // namespace robozoo
