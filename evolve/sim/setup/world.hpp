#pragma once
// The ODE world of one robot (docs/method.md section 2): one ODE body per rigid
// component, placed at its centre of mass and carrying one sphere geom per
// sphere (offset from the body origin) and the spheres' combined mass; one
// hinge per joint, anchored at the child sphere's centre, with stops at
// -/+range and a motor; the ground plane z = 0; gravity along -z.
//
// Geoms live in no space: contacts are found by evolve/sim/step/contacts in a fixed
// order, never by ODE's space traversal.
#include <vector>

#include <Eigen/Core>
#include <ode/ode.h>

#include "evolve/growth/robot.hpp"
#include "evolve/sim/params.hpp"

namespace robozoo {

class OdeWorld {
 public:
  /// Builds the world. The robot must pass check_robot(). Motors start off
  /// (zero speed, zero force).
  OdeWorld(const Robot& robot, const SimParams& params);
  ~OdeWorld();
  OdeWorld(const OdeWorld&) = delete;
  OdeWorld& operator=(const OdeWorld&) = delete;

  dWorldID world() const { return world_; }
  dJointGroupID contact_group() const { return contact_group_; }
  dGeomID ground() const { return ground_; }
  dBodyID body(int b) const { return bodies_[b]; }
  dGeomID geom(int sphere) const { return geoms_[sphere]; }
  dJointID hinge(int joint) const { return hinges_[joint]; }
  int num_bodies() const { return static_cast<int>(bodies_.size()); }
  int num_spheres() const { return static_cast<int>(geoms_.size()); }
  int num_joints() const { return static_cast<int>(hinges_.size()); }
  /// Total mass of body b (kg).
  double body_mass(int b) const { return body_mass_[b]; }
  double total_mass() const { return total_mass_; }

  /// World centre of a sphere (m).
  Eigen::Vector3d sphere_center(int sphere) const;
  /// Mass-weighted centre of the whole robot (m).
  Eigen::Vector3d center_of_mass() const;

 private:
  dWorldID world_ = nullptr;
  dJointGroupID contact_group_ = nullptr;
  dGeomID ground_ = nullptr;
  std::vector<dBodyID> bodies_;
  std::vector<dGeomID> geoms_;
  std::vector<dJointID> hinges_;
  std::vector<double> body_mass_;
  double total_mass_ = 0.0;
};

/// Mass of one sphere: density * 4/3 pi r^3 (kg).
double sphere_mass(const Sphere& s);

}  // namespace robozoo
