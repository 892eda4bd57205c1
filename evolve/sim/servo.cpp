#include "evolve/sim/servo.hpp"

#include <algorithm>
#include <cmath>

namespace robozoo {

double servo_speed(double target, double angle, const SimParams& p) {
  return std::clamp(p.servo_gain * (target - angle), -p.servo_max_speed, p.servo_max_speed);
}

std::vector<double> joint_side_moments(const Robot& robot) {
  const int nb = robot.num_bodies;
  // Body tree adjacency: (neighbour body, joint index).
  std::vector<std::vector<std::pair<int, int>>> adj(nb);
  for (size_t k = 0; k < robot.joints.size(); ++k) {
    const Joint& j = robot.joints[k];
    adj[j.parent_body].push_back({j.child_body, static_cast<int>(k)});
    adj[j.child_body].push_back({j.parent_body, static_cast<int>(k)});
  }
  std::vector<double> out;
  std::vector<int> side(nb), stack;
  for (size_t k = 0; k < robot.joints.size(); ++k) {
    const Joint& j = robot.joints[k];
    // Mark the child's side: bodies reachable from child_body without crossing joint k.
    std::fill(side.begin(), side.end(), 0);
    side[j.child_body] = 1;
    stack.assign(1, j.child_body);
    while (!stack.empty()) {
      const int b = stack.back();
      stack.pop_back();
      for (const auto& [nbh, jk] : adj[b])
        if (jk != static_cast<int>(k) && !side[nbh]) {
          side[nbh] = 1;
          stack.push_back(nbh);
        }
    }
    const Eigen::Vector3d& anchor = robot.spheres[j.sphere].center;
    double moment[2] = {0, 0};
    for (const Sphere& s : robot.spheres)
      moment[side[s.body]] += sphere_mass(s) * std::max((s.center - anchor).norm(), s.radius);
    out.push_back(std::min(moment[0], moment[1]));
  }
  return out;
}

std::vector<double> motor_torque_limits(const Robot& robot, const SimParams& p) {
  std::vector<double> m = joint_side_moments(robot);
  for (double& x : m) x *= p.motor_strength * p.gravity;
  return m;
}

void apply_servos(const OdeWorld& world, const Robot& robot, const std::vector<double>& outputs,
                  const std::vector<double>& limits, const SimParams& p) {
  for (size_t k = 0; k < robot.joints.size(); ++k) {
    const Joint& j = robot.joints[k];
    const dJointID h = world.hinge(static_cast<int>(k));
    const double target = outputs[j.neuron] * j.range;
    dJointSetHingeParam(h, dParamVel, servo_speed(target, dJointGetHingeAngle(h), p));
    dJointSetHingeParam(h, dParamFMax, limits[k]);
  }
}

}  // namespace robozoo
