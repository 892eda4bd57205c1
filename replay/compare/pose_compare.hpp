#pragma once
// A logged ROBOZOO_POSE against make_pose_message of the re-simulated state at
// the same step: every field but utime, naming the body (sphere, neuron,
// sensor) and the field.
#include "replay/compare/value_compare.hpp"
#include "robozoo/pose_t.hpp"

namespace robozoo::replay {

/// Adds every difference to `cmp` (context "pose", the logged step); returns
/// true when none was found. Arrays are compared only where their counts agree.
bool compare_pose(const pose_t& logged, const pose_t& recomputed, ValueComparer& cmp);

}  // namespace robozoo::replay
