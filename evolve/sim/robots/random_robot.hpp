#pragma once
// Random robots for stress tests, parameter tuning and benchmarks: trees of
// spheres in one horizontal plane, placed under growth's rules (docs/method.md
// section 2, growth steps 3-5 and 7) but with random choices instead of a CPPN:
// each new sphere's centre lies on its parent's horizontal circle of radius
// r_parent, its radius is clamp(r_parent * s, r_min, r_max) with s uniform in
// (0, 2), it is jointed with some probability (axis perpendicular to the
// parent->child direction, random half range), leaf joints are pruned, and
// the robot is shifted so the largest sphere rests on z = 0.
#include "evolve/core/rng.hpp"
#include "evolve/growth/robot.hpp"

namespace robozoo {

struct RandomRobotParams {
  int min_spheres = 1;                          ///< (count)
  int max_spheres = 50;                         ///< target count is uniform in [min, max] (count)
  double root_radius_min = 0.05;                ///< root radius drawn uniformly in [min, max] (m)
  double root_radius_max = 0.5;                 ///< (m)
  double r_min = 0.05;                          ///< smallest radius (m)
  double r_max = 0.5;                           ///< largest radius (m)
  double density_min = 1.0;                     ///< (mass per m^3)
  double density_max = 3.0;                     ///< (mass per m^3)
  double joint_probability = 0.5;               ///< a new sphere is jointed with this probability
  double max_joint_range = 1.5707963267948966;  ///< half range uniform in (0, max] (rad)
  double sensor_probability = 0.3;              ///< each sensor type on each sphere (probability)
  double link_probability = 0.8;                ///< each CTRNN weight drawn, else 0 (probability)
  double weight_max = 3.0;                      ///< weights v * max with v uniform in (-1, 1), 0 if |v| <= 0.2
  double tau_min = 0.05;                        ///< (s)
  double tau_max = 1.0;                         ///< (s)
  double bias_max = 3.0;                        ///< omega uniform in (-max, max)
  double bound = 2.0;                           ///< centres keep |x|, |y| <= bound (m)
  int max_attempts = 5000;                      ///< placement tries before giving up on the target count
};

/// A random robot; a pure function of the generator's state and the parameters.
Robot random_robot(Rng& rng, const RandomRobotParams& params);

}  // namespace robozoo
