#pragma once
// From a pruned GrownBody to a Robot model: bodies, joints, motor neurons and
// sensors numbered as docs/method.md section 2 and robot.hpp fix them.
#include "evolve/growth/body/grown_body.hpp"
#include "evolve/growth/robot.hpp"

namespace robozoo {

/// - Bodies: a body starts at the root and at every sphere that (still) has a
///   joint; every other sphere belongs to its parent's body. Bodies are numbered
///   by their first sphere in growth order.
/// - Joints: one per jointed sphere, in growth order; joint i is driven by motor
///   neuron i (Neuron::sphere = the jointed sphere, Sphere::motor_neuron = i).
/// - Sensors: by sphere (growth order), then type order Distance, Touch, Proprio,
///   Time.
/// Weight matrices are sized (sensors x neurons, neurons x neurons) and zero;
/// positions stay as grown (no vertical shift); r_term and simulate untouched.
/// Throws std::logic_error if a proprioceptive sensor sits on an unjointed sphere
/// (prune first).
Robot assemble_robot(const GrownBody& body);

}  // namespace robozoo
