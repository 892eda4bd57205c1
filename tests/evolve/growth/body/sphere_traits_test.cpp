#include "evolve/growth/body/sphere_traits.hpp"

#include <gtest/gtest.h>

#include "evolve/growth/growth.hpp"

namespace robozoo {
namespace {

TEST(SphereTraits, RadiusIsTheClampedScaledParentRadius) {
  const GrowthParams p;  // r in [0.05, 0.5]
  EXPECT_DOUBLE_EQ(sphere_radius(0.1, 0.5, p), 0.15);
  EXPECT_DOUBLE_EQ(sphere_radius(0.1, 0.0, p), 0.1);
  EXPECT_EQ(sphere_radius(0.1, -0.9, p), 0.05);
  EXPECT_EQ(sphere_radius(0.4, 0.9, p), 0.5);
  EXPECT_EQ(sphere_radius(0.05, -0.2, p), 0.05);
}

TEST(SphereTraits, DensityRisesFromRhoMinAtTheThreshold) {
  const GrowthParams p;  // rho in [1, 3], T = 0.7
  EXPECT_DOUBLE_EQ(sphere_density(1.0, p), 3.0);
  EXPECT_DOUBLE_EQ(sphere_density(0.85, p), 2.0);
  EXPECT_DOUBLE_EQ(sphere_density(0.7, p), 1.0);
  EXPECT_DOUBLE_EQ(sphere_density(-0.3, p), 1.0);  // the root below threshold
}

TEST(SphereTraits, SensorsAboveThresholdProprioceptionOnlyWithAJoint) {
  const GrowthParams p;
  CppnOutputs o{};
  o[kOutSensorDistance] = 0.71;
  o[kOutSensorTouch] = 0.7;  // not above
  o[kOutSensorProprio] = 0.9;
  o[kOutSensorTime] = 0.95;
  EXPECT_EQ(sensor_mask(o, true, p), kSensorDistance | kSensorProprio | kSensorTime);
  EXPECT_EQ(sensor_mask(o, false, p), kSensorDistance | kSensorTime);
  o = {};
  EXPECT_EQ(sensor_mask(o, true, p), 0);
}

}  // namespace
}  // namespace robozoo
