#include "evolve/growth/finish/assemble.hpp"

#include <stdexcept>
#include <string>

namespace robozoo {

Robot assemble_robot(const GrownBody& body) {
  Robot robot;
  robot.spheres = body.spheres;
  int bodies = 0;
  for (Sphere& s : robot.spheres) {
    if (s.parent >= s.index) throw std::logic_error("assemble_robot: spheres not in growth order");
    s.body = (s.parent < 0 || s.has_joint) ? bodies++ : robot.spheres[s.parent].body;
    s.motor_neuron = -1;
    if (s.has_joint) {
      const int i = static_cast<int>(robot.joints.size());
      s.motor_neuron = i;
      Joint j;
      j.sphere = s.index;
      j.parent_body = robot.spheres[s.parent].body;
      j.child_body = s.body;
      j.axis = s.joint_axis;
      j.range = s.joint_range;
      j.neuron = i;
      robot.joints.push_back(j);
      const Neuron& m = body.motors[s.index];
      robot.neurons.push_back(Neuron{s.index, m.tau, m.omega});
    } else if (s.sensors & kSensorProprio) {
      throw std::logic_error("assemble_robot: proprioceptive sensor on unjointed sphere " + std::to_string(s.index));
    }
    static constexpr SensorType kTypes[] = {SensorType::Distance, SensorType::Touch, SensorType::Proprio,
                                            SensorType::Time};
    static constexpr uint8_t kBits[] = {kSensorDistance, kSensorTouch, kSensorProprio, kSensorTime};
    for (int t = 0; t < 4; ++t)
      if (s.sensors & kBits[t]) robot.sensors.push_back(Sensor{s.index, kTypes[t]});
  }
  robot.num_bodies = bodies;
  const auto ns = static_cast<Eigen::Index>(robot.sensors.size());
  const auto nn = static_cast<Eigen::Index>(robot.neurons.size());
  robot.w_sensor_neuron = Eigen::MatrixXd::Zero(ns, nn);
  robot.w_neuron_neuron = Eigen::MatrixXd::Zero(nn, nn);
  return robot;
}

}  // namespace robozoo
