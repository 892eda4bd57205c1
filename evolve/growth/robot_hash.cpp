#include "evolve/growth/robot_hash.hpp"

#include <cstring>

#include "evolve/core/fnv1a.hpp"

namespace robozoo {

namespace {

struct Fnv : Fnv1a {
  void i64(int64_t v) { bytes(&v, sizeof v); }
  void f64(double v) {
    uint64_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    bytes(&bits, sizeof bits);
  }
  void vec(const Eigen::Vector3d& v) {
    f64(v.x());
    f64(v.y());
    f64(v.z());
  }
  void mat(const Eigen::MatrixXd& m) {
    i64(m.rows());
    i64(m.cols());
    for (Eigen::Index r = 0; r < m.rows(); ++r)
      for (Eigen::Index c = 0; c < m.cols(); ++c) f64(m(r, c));
  }
};

}  // namespace

uint64_t robot_hash(const Robot& robot) {
  Fnv f;
  f.i64(static_cast<int64_t>(robot.spheres.size()));
  for (const Sphere& s : robot.spheres) {
    f.i64(s.index);
    f.i64(s.parent);
    f.vec(s.center);
    f.f64(s.radius);
    f.f64(s.density);
    f.f64(s.matter);
    f.i64(s.body);
    f.i64(s.has_joint);
    f.vec(s.joint_axis);
    f.f64(s.joint_range);
    f.i64(s.motor_neuron);
    f.i64(s.cloud_angle_index);
    f.i64(s.sensors);
    f.i64(s.num_children);
    f.i64(s.joint_pruned);
  }
  f.i64(robot.num_bodies);
  f.i64(static_cast<int64_t>(robot.joints.size()));
  for (const Joint& j : robot.joints) {
    f.i64(j.sphere);
    f.i64(j.parent_body);
    f.i64(j.child_body);
    f.vec(j.axis);
    f.f64(j.range);
    f.i64(j.neuron);
  }
  f.i64(static_cast<int64_t>(robot.neurons.size()));
  for (const Neuron& n : robot.neurons) {
    f.i64(n.sphere);
    f.f64(n.tau);
    f.f64(n.omega);
  }
  f.i64(static_cast<int64_t>(robot.sensors.size()));
  for (const Sensor& s : robot.sensors) {
    f.i64(s.sphere);
    f.i64(static_cast<int64_t>(s.type));
  }
  f.mat(robot.w_sensor_neuron);
  f.mat(robot.w_neuron_neuron);
  f.f64(robot.r_term);
  f.i64(robot.simulate);
  f.f64(robot.vertical_shift);
  return f.h;
}

}  // namespace robozoo
