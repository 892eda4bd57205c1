#pragma once
// A robot as the renderer sees it: spheres with radii and the paper's colour
// rule (Figure 4: leaf spheres red, all others blue), read from a logged
// morphology. Positions come from the morphology (the starting pose) or from a
// pose (world centres of every sphere): no kinematics, no growth.
#include <vector>

#include <Eigen/Core>

#include "render/scene/scene.hpp"
#include "robozoo/morphology_t.hpp"
#include "robozoo/pose_t.hpp"
#include "runlog/robots/leaf_spheres.hpp"

namespace robozoo::render {

struct RobotShape {
  std::vector<double> radius;          ///< per sphere (m)
  std::vector<bool> leaf;              ///< per sphere
  std::vector<Eigen::Vector3d> start;  ///< starting centres (m), after growth's vertical shift
  std::vector<double> mass;            ///< per sphere: density x volume (kg)
  size_t size() const { return radius.size(); }
  /// Centre of mass of the spheres at these centres (m): where the fitness's
  /// distances are measured from, up to how the simulator sums overlapping spheres.
  Eigen::Vector3d mass_center(const std::vector<Eigen::Vector3d>& centers) const;
  /// Spheres to draw at the given centres (one per sphere).
  std::vector<SphereDraw> at(const std::vector<Eigen::Vector3d>& centers) const;
  std::vector<SphereDraw> at_start() const { return at(start); }
};

/// Throws std::invalid_argument when the morphology is inconsistent.
RobotShape shape_from_morphology(const morphology_t& m);

/// Centre of the spheres' volumes (m): where a camera follows.
Eigen::Vector3d volume_center(const std::vector<Eigen::Vector3d>& centers, const std::vector<double>& radii);

}  // namespace robozoo::render
