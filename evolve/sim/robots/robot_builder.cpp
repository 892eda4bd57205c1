#include "evolve/sim/robots/robot_builder.hpp"

#include <stdexcept>
#include <string>

namespace robozoo {

int RobotBuilder::add(Spec s) {
  const int i = size();
  if ((i == 0) != (s.sphere.parent < 0)) throw std::invalid_argument("RobotBuilder: add the root first, and only once");
  if (s.sphere.parent >= i)
    throw std::invalid_argument("RobotBuilder: parent " + std::to_string(s.sphere.parent) + " does not exist");
  if (!(s.sphere.radius > 0)) throw std::invalid_argument("RobotBuilder: radius must be > 0");
  s.sphere.index = i;
  if (s.sphere.parent >= 0) ++spheres_[s.sphere.parent].sphere.num_children;
  spheres_.push_back(s);
  return i;
}

int RobotBuilder::add_root(const Eigen::Vector3d& c, double radius, double density, uint8_t sensors) {
  Spec s;
  s.sphere.center = c;
  s.sphere.radius = radius;
  s.sphere.density = density;
  s.sphere.sensors = sensors;
  s.sphere.parent = -1;
  return add(s);
}

RobotBuilder::Spec RobotBuilder::child_spec(int parent, const Eigen::Vector3d& c, double radius, double density,
                                            uint8_t sensors) {
  Spec s;
  s.sphere.parent = parent;
  s.sphere.center = c;
  s.sphere.radius = radius;
  s.sphere.density = density;
  s.sphere.sensors = sensors;
  return s;
}

int RobotBuilder::add_fused(int parent, const Eigen::Vector3d& c, double radius, double density, uint8_t sensors) {
  if (parent < 0) throw std::invalid_argument("RobotBuilder: a fused sphere needs a parent");
  return add(child_spec(parent, c, radius, density, sensors));
}

int RobotBuilder::add_jointed(int parent, const Eigen::Vector3d& c, double radius, const Eigen::Vector3d& axis,
                              double range, double tau, double omega, double density, uint8_t sensors) {
  if (parent < 0) throw std::invalid_argument("RobotBuilder: a jointed sphere needs a parent");
  Spec s = child_spec(parent, c, radius, density, sensors);
  s.sphere.has_joint = true;
  s.sphere.joint_axis = axis.normalized();
  s.sphere.joint_range = range;
  s.tau = tau;
  s.omega = omega;
  return add(s);
}

Robot RobotBuilder::build(bool rest_on_ground) const {
  if (spheres_.empty()) throw std::invalid_argument("RobotBuilder: no spheres");
  Robot r;
  int largest = 0;
  for (const Spec& s : spheres_) {
    if (s.sphere.radius > spheres_[largest].sphere.radius) largest = s.sphere.index;
  }
  const double dz = rest_on_ground ? spheres_[largest].sphere.radius - spheres_[largest].sphere.center.z() : 0.0;
  r.vertical_shift = dz;
  for (const Spec& spec : spheres_) {
    Sphere s = spec.sphere;
    s.center.z() += dz;
    if (s.parent < 0) {
      s.body = r.num_bodies++;
    } else if (s.has_joint) {
      s.body = r.num_bodies++;
      s.motor_neuron = static_cast<int>(r.neurons.size());
      Joint j;
      j.sphere = s.index;
      j.parent_body = r.spheres[s.parent].body;
      j.child_body = s.body;
      j.axis = s.joint_axis;
      j.range = s.joint_range;
      j.neuron = s.motor_neuron;
      r.joints.push_back(j);
      r.neurons.push_back({s.index, spec.tau, spec.omega});
    } else {
      s.body = r.spheres[s.parent].body;
    }
    const SensorType types[4] = {SensorType::Distance, SensorType::Touch, SensorType::Proprio, SensorType::Time};
    const uint8_t bits[4] = {kSensorDistance, kSensorTouch, kSensorProprio, kSensorTime};
    for (int t = 0; t < 4; ++t)
      if (s.sensors & bits[t]) r.sensors.push_back({s.index, types[t]});
    r.spheres.push_back(s);
  }
  r.w_sensor_neuron = Eigen::MatrixXd::Zero(r.sensors.size(), r.neurons.size());
  r.w_neuron_neuron = Eigen::MatrixXd::Zero(r.neurons.size(), r.neurons.size());
  return r;
}

int sensor_index(const Robot& robot, int sphere, SensorType type) {
  for (size_t k = 0; k < robot.sensors.size(); ++k)
    if (robot.sensors[k].sphere == sphere && robot.sensors[k].type == type) return static_cast<int>(k);
  return -1;
}

int neuron_index(const Robot& robot, int sphere) {
  for (size_t i = 0; i < robot.neurons.size(); ++i)
    if (robot.neurons[i].sphere == sphere) return static_cast<int>(i);
  return -1;
}

}  // namespace robozoo
