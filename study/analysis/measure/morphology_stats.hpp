#pragma once
// The body-plan statistics of the paper's Figure 2, for one robot.
#include <cstdint>
#include <vector>

#include "robozoo/morphology_t.hpp"

namespace robozoo {

struct MorphologyStatsParams {
  /// A sphere touched the ground when its centre height minus its radius was at
  /// most this at some logged pose (m). ODE's soft contacts let a resting sphere
  /// sink slightly below z = 0 and poses are logged every k-th step, so a small
  /// positive tolerance (1/20 of the root's radius) counts a sphere that rested or
  /// bounced on the ground.
  double ground_epsilon = 0.005;
};

struct MorphologyStats {
  double spheres = 0;           ///< spheres (count)
  double leaves = 0;            ///< spheres other than the root with no child (count; paper's footnote 1)
  double joints = 0;            ///< hinge joints after pruning (count)
  double distance_sensors = 0;  ///< spheres carrying a distance sensor (count)
  double touch_sensors = 0;     ///< spheres carrying a touch sensor (count)
  double proprio_sensors = 0;   ///< spheres carrying a proprioceptive sensor (count)
  double time_sensors = 0;      ///< spheres carrying a time sensor (count)
  double mean_radius = 0;       ///< mean sphere radius (m)
  double radius_variance = 0;   ///< variance of the radii within the robot, population form (1/n) (m^2)
  double max_depth = 0;         ///< most parent links between a sphere and the root (count)
  bool ground_known = false;    ///< a pose stream was available for the ground statistics
  double ground_spheres = 0;    ///< spheres that touched the ground at some logged pose (count; 0 when unknown)
  double ground_fraction = 0;   ///< ground_spheres / spheres (0 when unknown)
};

/// Statistics of `m`. `min_center_z`, when given, holds the lowest logged
/// centre height of every sphere (m) over the robot's pose stream; without it
/// the ground statistics are 0 and ground_known is false. Throws
/// std::invalid_argument for a malformed tree or a pose stream of another size.
MorphologyStats morphology_stats(const morphology_t& m, const std::vector<double>* min_center_z,
                                 const MorphologyStatsParams& params = {});

}  // namespace robozoo
