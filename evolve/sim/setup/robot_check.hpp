#pragma once
// Validates a Robot model before it is simulated: the indices, sizes and
// conventions of evolve/growth/robot.hpp that the simulation relies on.
#include "evolve/growth/robot.hpp"

namespace robozoo {

/// Throws std::invalid_argument naming the first problem: spheres indexed in
/// growth order with earlier parents, positive finite radii and densities,
/// bodies numbered 0..num_bodies-1 and all used, one joint per jointed sphere
/// between its parent's body and its own (different) body, unit axes, ranges
/// >= 0, joints forming a tree over the bodies, neurons on jointed spheres,
/// proprioceptive sensors only on jointed spheres, weight matrices of the right
/// sizes with finite entries, neuron tau > 0.
void check_robot(const Robot& robot);

}  // namespace robozoo
