#include "evolve/growth/body/hinge.hpp"
#include "evolve/math/trig.hpp"

#include <cmath>
#include <stdexcept>

#include <Eigen/Geometry>

namespace robozoo {

Eigen::Vector3d hinge_axis(const Eigen::Vector3d& parent_to_child, double theta) {
  const double len = parent_to_child.norm();
  if (!(len > 0)) throw std::logic_error("hinge_axis: child centre coincides with its parent's");
  const Eigen::Vector3d a = parent_to_child / len;
  Eigen::Vector3d n = a.cross(Eigen::Vector3d::UnitZ());
  if (n.norm() < 1e-12) n = a.cross(Eigen::Vector3d::UnitX());
  n.normalize();
  // Rodrigues for n perpendicular to a: n cos(phi) + (a x n) sin(phi).
  const double phi = M_PI * theta;
  Eigen::Vector3d axis = n * math::cos(phi) + a.cross(n) * math::sin(phi);
  return axis.normalized();
}

double hinge_range(double j, const GrowthParams& p) { return (j - p.t_joint) / (1.0 - p.t_joint) * p.max_joint_range; }

double motor_tau(double tau_out, const GrowthParams& p) {
  return p.tau_min + (p.tau_max - p.tau_min) * (tau_out + 1.0) / 2.0;
}

double motor_omega(double omega_out, const GrowthParams& p) { return omega_out * p.bias_max; }

}  // namespace robozoo
