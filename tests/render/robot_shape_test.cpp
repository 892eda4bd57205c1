#include "render/robot_shape.hpp"

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

TEST(RobotShape, VolumeCentreWeighsBySize) {
  const Eigen::Vector3d c = volume_center({{0, 0, 0}, {3, 0, 0}}, {2.0, 1.0});
  EXPECT_NEAR(c.x(), 3.0 / 9.0, 1e-12);
}

}  // namespace
}  // namespace robozoo::render
