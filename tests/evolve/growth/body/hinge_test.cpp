#include "evolve/growth/body/hinge.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "evolve/core/rng.hpp"

namespace robozoo {
namespace {

void expect_near(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  EXPECT_NEAR((a - b).norm(), 0.0, 1e-12) << a.transpose() << " vs " << b.transpose();
}

TEST(Hinge, AxisIsAxDRotatedAboutA) {
  const Eigen::Vector3d a(1, 0, 0);
  // a x (0,0,1) = (0,-1,0); rotating about +x by +90 deg takes -y to -z.
  expect_near(hinge_axis(a, 0.0), Eigen::Vector3d(0, -1, 0));
  expect_near(hinge_axis(a, 0.5), Eigen::Vector3d(0, 0, -1));
  expect_near(hinge_axis(a, 1.0), Eigen::Vector3d(0, 1, 0));
  expect_near(hinge_axis(a, -0.5), Eigen::Vector3d(0, 0, 1));
  // Length of the parent -> child vector does not matter.
  expect_near(hinge_axis(Eigen::Vector3d(0, 0.07, 0), 0.0), Eigen::Vector3d(1, 0, 0));
}

TEST(Hinge, AxisIsAUnitNormalOfA) {
  Rng rng(5);
  for (int i = 0; i < 200; ++i) {
    const double phi = rng.uniform(0, 2 * M_PI);
    const Eigen::Vector3d a(std::cos(phi), std::sin(phi), 0);
    const Eigen::Vector3d n = hinge_axis(0.3 * a, rng.uniform(-1, 1));
    EXPECT_NEAR(n.norm(), 1.0, 1e-12);
    EXPECT_NEAR(n.dot(a), 0.0, 1e-12);
  }
  // Vertical a (not produced by growth) still gives a unit normal.
  const Eigen::Vector3d v = hinge_axis(Eigen::Vector3d(0, 0, 1), 0.3);
  EXPECT_NEAR(v.norm(), 1.0, 1e-12);
  EXPECT_NEAR(v.z(), 0.0, 1e-12);
  EXPECT_THROW(hinge_axis(Eigen::Vector3d::Zero(), 0.0), std::logic_error);
}

TEST(Hinge, RangeAndMotorMappings) {
  const GrowthParams p;
  EXPECT_DOUBLE_EQ(hinge_range(1.0, p), M_PI / 2);
  EXPECT_NEAR(hinge_range(0.7, p), 0.0, 1e-15);
  EXPECT_DOUBLE_EQ(hinge_range(0.85, p), M_PI / 4);
  EXPECT_DOUBLE_EQ(motor_tau(-1.0, p), p.tau_min);
  EXPECT_DOUBLE_EQ(motor_tau(1.0, p), p.tau_max);
  EXPECT_DOUBLE_EQ(motor_tau(0.0, p), (p.tau_min + p.tau_max) / 2);
  EXPECT_DOUBLE_EQ(motor_omega(-0.5, p), -1.5);
  EXPECT_DOUBLE_EQ(motor_omega(1.0, p), p.bias_max);
}

}  // namespace
}  // namespace robozoo
