#include "render/scene/robot_shape.hpp"

#include <gtest/gtest.h>

#include "tests/render/fixtures.hpp"

namespace robozoo::render {
namespace {

TEST(RobotShape, LeavesAreSpheresWithoutChildren) {
  const morphology_t m = testing::known_robot();
  EXPECT_EQ(leaf_spheres(m), (std::vector<bool>{false, false, true, true}));
  const RobotShape s = shape_from_morphology(m);
  ASSERT_EQ(s.size(), 4u);
  EXPECT_EQ(s.radius[2], 0.15);
  EXPECT_EQ(s.start[1], Eigen::Vector3d(0.9, 0, 0.2));
  const auto draws = s.at_start();
  EXPECT_TRUE(draws[3].leaf);
  EXPECT_FALSE(draws[0].leaf);
  EXPECT_THROW(s.at({Eigen::Vector3d::Zero()}), std::invalid_argument);
}

TEST(RobotShape, RootAloneIsALeaf) {
  morphology_t m = testing::known_robot();
  m.spheres.resize(1);
  m.num_spheres = 1;
  EXPECT_EQ(leaf_spheres(m), std::vector<bool>{true});
}

TEST(RobotShape, InconsistentMorphologyIsRejected) {
  morphology_t m = testing::known_robot();
  m.spheres[2].parent = 3;  // a parent added after its child
  EXPECT_THROW(shape_from_morphology(m), std::invalid_argument);
  m = testing::known_robot();
  m.spheres[1].radius = -1;
  EXPECT_THROW(shape_from_morphology(m), std::invalid_argument);
}

TEST(RobotShape, MassCentreWeighsByDensityAndVolume) {
  morphology_t m = testing::known_robot();
  const RobotShape s = shape_from_morphology(m);
  EXPECT_NEAR(s.mass[0], 4.0 / 3.0 * M_PI * 0.25 * 0.25 * 0.25, 1e-12);
  std::vector<Eigen::Vector3d> c = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}};
  const double m0 = s.mass[0], m1 = s.mass[1], m2 = s.mass[2], m3 = s.mass[3];
  EXPECT_NEAR(s.mass_center(c).x(), (m1 + 2 * m2 + 3 * m3) / (m0 + m1 + m2 + m3), 1e-12);
  m.spheres[2].density = 10.0;  // a heavy leaf pulls it over
  EXPECT_GT(shape_from_morphology(m).mass_center(c).x(), s.mass_center(c).x());
  EXPECT_THROW(s.mass_center({{0, 0, 0}}), std::invalid_argument);
}

TEST(RobotShape, VolumeCentreWeighsBySize) {
  const Eigen::Vector3d c = volume_center({{0, 0, 0}, {3, 0, 0}}, {2.0, 1.0});
  EXPECT_NEAR(c.x(), 3.0 / 9.0, 1e-12);
}

}  // namespace
}  // namespace robozoo::render
