#pragma once
// A joint's hinge and motor neuron from the CPPN outputs at the child's point
// (paper 2.3; docs/method.md section 2, outputs table).
#include <Eigen/Core>

#include "evolve/growth/params.hpp"

namespace robozoo {

/// Hinge axis: n = normalize(a x d), a = unit vector parent -> child, d = (0, 0, 1),
/// rotated about a by pi * theta (right-hand rule). If a is parallel to d
/// (impossible in growth, where all centres share one height) d = (1, 0, 0) is
/// used instead. `parent_to_child` need not be unit; it must not be zero
/// (std::logic_error).
Eigen::Vector3d hinge_axis(const Eigen::Vector3d& parent_to_child, double theta);

/// Half range of motion (j - T) / (1 - T) * max_joint_range (rad), for j > T.
double hinge_range(double j, const GrowthParams& p);

/// Motor neuron time constant tau_min + (tau_max - tau_min)(tau + 1) / 2 (s).
double motor_tau(double tau_out, const GrowthParams& p);

/// Motor neuron bias omega * bias_max (dimensionless).
double motor_omega(double omega_out, const GrowthParams& p);

}  // namespace robozoo
