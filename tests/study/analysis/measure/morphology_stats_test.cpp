#include "study/analysis/measure/morphology_stats.hpp"

#include <gtest/gtest.h>

#include "tests/study/analysis/builders.hpp"

namespace robozoo {
namespace {

using testing::make_morphology;

// Root 0; 1 and 4 on the root; 2 on 1; 3 on 2. Leaves: 3 and 4. Depth: 3.
morphology_t robot() {
  return make_morphology({-1, 0, 1, 2, 0}, {0.1, 0.2, 0.2, 0.3, 0.2}, {false, true, true, false, false},
                         {1 | 8, 2, 2 | 4, 0, 1 | 2});
}

TEST(MorphologyStats, CountsByHand) {
  const MorphologyStats s = morphology_stats(robot(), nullptr);
  EXPECT_EQ(s.spheres, 5);
  EXPECT_EQ(s.leaves, 2);
  EXPECT_EQ(s.joints, 2);
  EXPECT_EQ(s.distance_sensors, 2);  // spheres 0 and 4
  EXPECT_EQ(s.touch_sensors, 3);     // 1, 2, 4
  EXPECT_EQ(s.proprio_sensors, 1);   // 2
  EXPECT_EQ(s.time_sensors, 1);      // 0
  EXPECT_EQ(s.max_depth, 3);
  // Radii 0.1, 0.2, 0.2, 0.3, 0.2: mean 0.2; squared deviations 0.01 + 0 + 0 + 0.01 + 0, / 5 = 0.004.
  EXPECT_NEAR(s.mean_radius, 0.2, 1e-15);
  EXPECT_NEAR(s.radius_variance, 0.004, 1e-15);
  EXPECT_FALSE(s.ground_known);
  EXPECT_EQ(s.ground_spheres, 0);
}

TEST(MorphologyStats, GroundContactFromLowestCentres) {
  // Lowest centre heights over a pose stream. Sphere 0 (r 0.1) rested at 0.098,
  // sphere 1 (r 0.2) came down to 0.204 (within 5 mm), sphere 2 (r 0.2) stayed at
  // 0.3, sphere 3 (r 0.3) at 0.31 (1 cm above: not touching), sphere 4 (r 0.2) at 0.2.
  const std::vector<double> min_z = {0.098, 0.204, 0.3, 0.31, 0.2};
  const MorphologyStats s = morphology_stats(robot(), &min_z);
  EXPECT_TRUE(s.ground_known);
  EXPECT_EQ(s.ground_spheres, 3);
  EXPECT_NEAR(s.ground_fraction, 0.6, 1e-15);
  MorphologyStatsParams strict;
  strict.ground_epsilon = 0.0;
  EXPECT_EQ(morphology_stats(robot(), &min_z, strict).ground_spheres, 2);
  const std::vector<double> wrong_size = {0.1, 0.2};
  EXPECT_THROW(morphology_stats(robot(), &wrong_size), std::invalid_argument);
}

TEST(MorphologyStats, TheRootAloneHasNoLeafAndDepthZero) {
  const MorphologyStats s = morphology_stats(make_morphology({-1}), nullptr);
  EXPECT_EQ(s.spheres, 1);
  EXPECT_EQ(s.leaves, 0);
  EXPECT_EQ(s.max_depth, 0);
  EXPECT_EQ(s.radius_variance, 0);
}

}  // namespace
}  // namespace robozoo
