#pragma once
// Joint actuation (docs/method.md section 2): a motor neuron's output o in (-1, 1)
// sets its hinge's target angle o * range; a velocity servo drives the hinge
// towards it with speed gain * (target - angle), capped at servo_max_speed, and
// a torque limit that scales with the masses the hinge moves.
#include <vector>

#include "evolve/growth/robot.hpp"
#include "evolve/sim/params.hpp"
#include "evolve/sim/setup/world.hpp"

namespace robozoo {

/// Commanded joint speed (rad/s) for a target and a current angle (rad).
double servo_speed(double target, double angle, const SimParams& params);

/// Per joint (robot.joints order), the moment the torque limit scales with:
/// the smaller, over the two bodies the hinge joins, of sum(sphere mass *
/// lever) over the body's spheres, where a sphere's lever is its distance from
/// the anchor, and at least its radius (so a body that is a single sphere
/// around the anchor still gets a torque). gravity times it is the largest
/// gravity torque that body alone exerts about the anchor. Only the two joined
/// bodies count, not what hangs beyond them: a motor's torque acts on them
/// first, and scaling by whole limbs let a hinge between two tiny bodies in a
/// long chain spin them up until the solver failed (24 % faults on robots grown
/// from random CPPNs, against 0.3 % this way). Units kg m; grown positions.
std::vector<double> joint_body_moments(const Robot& robot);

/// Torque limits (N m) per joint: motor_strength * gravity * body moment.
std::vector<double> motor_torque_limits(const Robot& robot, const SimParams& params);

/// Sets every hinge's motor speed towards targets[i] = outputs[neuron] * range,
/// from the hinges' current angles (rad, robot.joints order: what
/// dJointGetHingeAngle reads at this instant). The torque limits are set once
/// by set_servo_torque_limits.
void apply_servos(const OdeWorld& world, const Robot& robot, const std::vector<double>& neuron_outputs,
                  const std::vector<double>& angles, const SimParams& params);

/// Sets every hinge's motor torque limit (N m, robot.joints order).
void set_servo_torque_limits(const OdeWorld& world, const std::vector<double>& torque_limits);

}  // namespace robozoo
