#include "evolve/sim/step/servo.hpp"

#include <algorithm>
#include <cmath>

namespace robozoo {

double servo_speed(double target, double angle, const SimParams& p) {
  return std::clamp(p.servo_gain * (target - angle), -p.servo_max_speed, p.servo_max_speed);
}

std::vector<double> joint_body_moments(const Robot& robot) {
  std::vector<double> out;
  out.reserve(robot.joints.size());
  for (const Joint& j : robot.joints) {
    const Eigen::Vector3d& anchor = robot.spheres[j.sphere].center;
    double parent = 0, child = 0;
    for (const Sphere& s : robot.spheres) {
      if (s.body != j.parent_body && s.body != j.child_body) continue;
      const double m = sphere_mass(s) * std::max((s.center - anchor).norm(), s.radius);
      (s.body == j.parent_body ? parent : child) += m;
    }
    out.push_back(std::min(parent, child));
  }
  return out;
}

std::vector<double> motor_torque_limits(const Robot& robot, const SimParams& p) {
  std::vector<double> m = joint_body_moments(robot);
  for (double& x : m) x *= p.motor_strength * p.gravity;
  return m;
}

void apply_servos(const OdeWorld& world, const Robot& robot, const std::vector<double>& outputs,
                  const std::vector<double>& angles, const SimParams& p) {
  for (size_t k = 0; k < robot.joints.size(); ++k) {
    const Joint& j = robot.joints[k];
    const double target = outputs[j.neuron] * j.range;
    dJointSetHingeParam(world.hinge(static_cast<int>(k)), dParamVel, servo_speed(target, angles[k], p));
  }
}

void set_servo_torque_limits(const OdeWorld& world, const std::vector<double>& limits) {
  for (int k = 0; k < world.num_joints(); ++k) dJointSetHingeParam(world.hinge(k), dParamFMax, limits[k]);
}

}  // namespace robozoo
