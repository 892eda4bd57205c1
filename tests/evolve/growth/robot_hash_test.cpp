#include "evolve/growth/robot_hash.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <vector>

namespace robozoo {
namespace {

Robot sample() {
  Robot r;
  r.spheres.resize(2);
  r.spheres[1].index = 1;
  r.spheres[1].parent = 0;
  r.spheres[1].has_joint = true;
  r.joints.resize(1);
  r.neurons.resize(1);
  r.sensors = {Sensor{0, SensorType::Touch}};
  r.w_sensor_neuron = Eigen::MatrixXd::Constant(1, 1, 0.5);
  r.w_neuron_neuron = Eigen::MatrixXd::Constant(1, 1, -0.5);
  return r;
}

TEST(RobotHash, EqualRobotsEqualHashesAnyChangeShows) {
  EXPECT_EQ(robot_hash(sample()), robot_hash(sample()));
  const uint64_t base = robot_hash(sample());
  const std::vector<std::function<void(Robot&)>> edits = {
      [](Robot& r) { r.spheres[1].center.z() = 1e-300; },
      [](Robot& r) { r.spheres[0].radius += 1e-17; },
      [](Robot& r) { r.spheres[1].joint_pruned = true; },
      [](Robot& r) { r.spheres[1].sensors = kSensorTime; },
      [](Robot& r) { r.joints[0].axis.x() = 0.5; },
      [](Robot& r) { r.neurons[0].omega = 0.1; },
      [](Robot& r) { r.sensors[0].type = SensorType::Time; },
      [](Robot& r) { r.w_sensor_neuron(0, 0) = 0.0; },
      [](Robot& r) { r.w_neuron_neuron.resize(0, 0); },
      [](Robot& r) { r.r_term = 2.0; },
      [](Robot& r) { r.simulate = true; },
      [](Robot& r) { r.vertical_shift = 0.1; },
      [](Robot& r) { r.num_bodies = 2; },
  };
  for (size_t i = 0; i < edits.size(); ++i) {
    Robot r = sample();
    edits[i](r);
    EXPECT_NE(robot_hash(r), base) << "edit " << i;
  }
}

}  // namespace
}  // namespace robozoo
