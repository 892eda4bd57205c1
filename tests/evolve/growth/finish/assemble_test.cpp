#include "evolve/growth/finish/assemble.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace robozoo {
namespace {

// root 0; 1 fused to 0; 2 jointed to 1; 3 fused to 2; 4 jointed to 0; 5 fused to 0.
GrownBody body() {
  GrownBody b;
  const int parents[] = {-1, 0, 1, 2, 0, 0};
  const bool joints[] = {false, false, true, false, true, false};
  const uint8_t sensors[] = {kSensorTime | kSensorDistance,
                             0,
                             kSensorProprio | kSensorTouch,
                             kSensorTouch,
                             kSensorDistance | kSensorTime | kSensorProprio,
                             0};
  for (int i = 0; i < 6; ++i) {
    Sphere s;
    s.index = i;
    s.parent = parents[i];
    s.has_joint = joints[i];
    s.joint_axis = Eigen::Vector3d(0, 0, joints[i] ? (i == 2 ? 1.0 : -1.0) : 0.0);
    s.joint_range = joints[i] ? 0.1 * i : 0.0;
    s.sensors = sensors[i];
    s.body = 99;  // growth-time component ids are ignored
    s.center = Eigen::Vector3d(0.1 * i, 0, 0);
    b.spheres.push_back(s);
    b.motors.push_back(Neuron{i, 0.2 + i, -0.5 * i});
  }
  return b;
}

TEST(Assemble, NumbersBodiesJointsNeuronsAndSensors) {
  const Robot r = assemble_robot(body());
  // Bodies by first sphere: {0, 1, 5} = 0, {2, 3} = 1, {4} = 2.
  const int want_body[] = {0, 0, 1, 1, 2, 0};
  for (int i = 0; i < 6; ++i) EXPECT_EQ(r.spheres[i].body, want_body[i]) << i;
  EXPECT_EQ(r.num_bodies, 3);
  ASSERT_EQ(r.joints.size(), 2u);
  EXPECT_EQ(r.joints[0].sphere, 2);
  EXPECT_EQ(r.joints[0].parent_body, 0);
  EXPECT_EQ(r.joints[0].child_body, 1);
  EXPECT_EQ(r.joints[0].axis, Eigen::Vector3d(0, 0, 1));
  EXPECT_DOUBLE_EQ(r.joints[0].range, 0.2);
  EXPECT_EQ(r.joints[0].neuron, 0);
  EXPECT_EQ(r.joints[1].sphere, 4);
  EXPECT_EQ(r.joints[1].parent_body, 0);
  EXPECT_EQ(r.joints[1].child_body, 2);
  EXPECT_EQ(r.joints[1].neuron, 1);
  ASSERT_EQ(r.neurons.size(), 2u);
  EXPECT_EQ(r.neurons[0].sphere, 2);
  EXPECT_DOUBLE_EQ(r.neurons[0].tau, 2.2);
  EXPECT_DOUBLE_EQ(r.neurons[0].omega, -1.0);
  EXPECT_EQ(r.neurons[1].sphere, 4);
  EXPECT_EQ(r.spheres[2].motor_neuron, 0);
  EXPECT_EQ(r.spheres[4].motor_neuron, 1);
  EXPECT_EQ(r.spheres[3].motor_neuron, -1);
  // Sensors by sphere, then Distance, Touch, Proprio, Time.
  const std::pair<int, SensorType> want[] = {
      {0, SensorType::Distance}, {0, SensorType::Time},     {2, SensorType::Touch},   {2, SensorType::Proprio},
      {3, SensorType::Touch},    {4, SensorType::Distance}, {4, SensorType::Proprio}, {4, SensorType::Time}};
  ASSERT_EQ(r.sensors.size(), 8u);
  for (size_t k = 0; k < 8; ++k) {
    EXPECT_EQ(r.sensors[k].sphere, want[k].first) << k;
    EXPECT_EQ(r.sensors[k].type, want[k].second) << k;
  }
  EXPECT_EQ(r.w_sensor_neuron, Eigen::MatrixXd::Zero(8, 2));
  EXPECT_EQ(r.w_neuron_neuron, Eigen::MatrixXd::Zero(2, 2));
  EXPECT_EQ(r.spheres[3].center, Eigen::Vector3d(0.1 * 3, 0, 0));  // positions untouched
}

TEST(Assemble, RejectsProprioceptionWithoutAJoint) {
  GrownBody b = body();
  b.spheres[1].sensors = kSensorProprio;
  EXPECT_THROW(assemble_robot(b), std::logic_error);
}

}  // namespace
}  // namespace robozoo
