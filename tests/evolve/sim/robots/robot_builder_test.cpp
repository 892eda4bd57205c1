#include "evolve/sim/robots/robot_builder.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

#include "evolve/sim/setup/robot_check.hpp"

namespace robozoo {
namespace {

TEST(RobotBuilder, NumbersBodiesJointsNeuronsAndSensorsInGrowthOrder) {
  RobotBuilder b;
  const int root = b.add_root({0, 0, 0}, 0.1, 1.0, kSensorDistance);
  const int j1 =
      b.add_jointed(root, {0.1, 0, 0}, 0.2, {0, 2, 0}, 0.5, 0.3, 0.7, 2.0, kSensorTime | kSensorProprio | kSensorTouch);
  b.add_fused(j1, {0.3, 0, 0}, 0.1);
  const int j2 = b.add_jointed(root, {-0.1, 0, 0}, 0.1, {0, 0, 1}, 0.25);
  b.add_fused(j2, {-0.2, 0, 0}, 0.05);
  const Robot r = b.build();
  ASSERT_NO_THROW(check_robot(r));
  ASSERT_EQ(r.spheres.size(), 5u);
  EXPECT_EQ(r.num_bodies, 3);
  EXPECT_EQ(r.spheres[2].body, 1);  // fused to the first jointed sphere
  EXPECT_EQ(r.spheres[3].body, 2);
  ASSERT_EQ(r.joints.size(), 2u);
  EXPECT_EQ(r.joints[0].sphere, 1);
  EXPECT_EQ(r.joints[0].parent_body, 0);
  EXPECT_EQ(r.joints[0].child_body, 1);
  EXPECT_DOUBLE_EQ(r.joints[0].axis.y(), 1.0);  // normalised
  EXPECT_EQ(r.joints[1].neuron, 1);
  ASSERT_EQ(r.neurons.size(), 2u);
  EXPECT_DOUBLE_EQ(r.neurons[0].tau, 0.3);
  EXPECT_DOUBLE_EQ(r.neurons[0].omega, 0.7);
  // Sensors by sphere, then type order Distance, Touch, Proprio, Time.
  ASSERT_EQ(r.sensors.size(), 4u);
  EXPECT_EQ(r.sensors[0].type, SensorType::Distance);
  EXPECT_EQ(r.sensors[1].type, SensorType::Touch);
  EXPECT_EQ(r.sensors[2].type, SensorType::Proprio);
  EXPECT_EQ(r.sensors[3].type, SensorType::Time);
  EXPECT_EQ(sensor_index(r, 1, SensorType::Time), 3);
  EXPECT_EQ(sensor_index(r, 0, SensorType::Time), -1);
  EXPECT_EQ(neuron_index(r, 3), 1);
  EXPECT_EQ(r.w_sensor_neuron.rows(), 4);
  EXPECT_EQ(r.w_sensor_neuron.cols(), 2);
  EXPECT_EQ(r.w_neuron_neuron.rows(), 2);
  EXPECT_EQ(r.spheres[0].num_children, 2);
  // The largest sphere (radius 0.2) rests on the ground.
  EXPECT_DOUBLE_EQ(r.vertical_shift, 0.2);
  for (const Sphere& s : r.spheres) EXPECT_DOUBLE_EQ(s.center.z(), 0.2);
}

TEST(RobotBuilder, RejectsMisuse) {
  RobotBuilder b;
  EXPECT_THROW(b.build(), std::invalid_argument);
  EXPECT_THROW(b.add_fused(0, {0, 0, 0}, 0.1), std::invalid_argument);  // no root yet
  b.add_root({0, 0, 0}, 0.1);
  EXPECT_THROW(b.add_root({0, 0, 0}, 0.1), std::invalid_argument);
  EXPECT_THROW(b.add_fused(5, {0, 0, 0}, 0.1), std::invalid_argument);
  EXPECT_THROW(b.add_fused(0, {0, 0, 0}, 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace robozoo
