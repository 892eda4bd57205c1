#pragma once
// The raw result of growth steps 1-4 (docs/method.md section 2), before pruning:
// every sphere in growth order with its joint and sensors as grown.
#include <vector>

#include "evolve/growth/robot.hpp"

namespace robozoo {

struct GrownBody {
  /// Growth order; centres before the vertical shift (all at z = 0). Sphere::body
  /// holds the growth-time rigid component (see placement.hpp); motor_neuron is
  /// still -1 (neurons are numbered when the robot is assembled).
  std::vector<Sphere> spheres;
  /// Per sphere (same index): the motor neuron's tau and omega; meaningful only
  /// where spheres[i].has_joint (Neuron::sphere = i).
  std::vector<Neuron> motors;
  int num_components = 0;  ///< growth-time rigid components (count)
};

}  // namespace robozoo
