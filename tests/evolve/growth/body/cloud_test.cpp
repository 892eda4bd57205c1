#include "evolve/growth/body/cloud.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace robozoo {
namespace {

TEST(Cloud, SixHundredTwentyNinePointsOnTheHorizontalCircle) {
  const GrowthParams p;
  const Cloud cloud(p);
  ASSERT_EQ(cloud.size(), 629);
  const Eigen::Vector3d c(0.3, -0.2, 0.0);
  EXPECT_EQ(cloud.point(c, 0.1, 0), Eigen::Vector3d(0.4, -0.2, 0.0));
  for (int k : {1, 157, 314, 500, 628}) {
    const Eigen::Vector3d x = cloud.point(c, 0.1, k);
    EXPECT_DOUBLE_EQ(cloud.angle(k), k * 0.01);
    EXPECT_NEAR((x - c).norm(), 0.1, 1e-15);
    EXPECT_EQ(x.z(), c.z());
    EXPECT_NEAR(std::atan2(x.y() - c.y(), x.x() - c.x()), std::remainder(k * 0.01, 2 * M_PI), 1e-12);
  }
  // The last point, 6.28 rad, stops short of a full turn (2 pi = 6.2832).
  EXPECT_LT(cloud.angle(628), 2 * M_PI);
  EXPECT_GT(cloud.angle(628) + 0.01, 2 * M_PI);
}

TEST(Cloud, FollowsTheParameters) {
  GrowthParams p;
  p.cloud_points = 4;
  p.cloud_step = M_PI / 2;
  const Cloud cloud(p);
  ASSERT_EQ(cloud.size(), 4);
  const Eigen::Vector3d o = Eigen::Vector3d::Zero();
  EXPECT_NEAR((cloud.point(o, 2.0, 1) - Eigen::Vector3d(0, 2, 0)).norm(), 0, 1e-15);
  EXPECT_NEAR((cloud.point(o, 2.0, 2) - Eigen::Vector3d(-2, 0, 0)).norm(), 0, 1e-15);
}

}  // namespace
}  // namespace robozoo
