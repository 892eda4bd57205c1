#pragma once
// Growth step 5 (paper 2.3; docs/method.md section 2): pruning leaf joints.
#include "evolve/growth/body/grown_body.hpp"

namespace robozoo {

/// A leaf sphere (no sphere attached to it) that grew a joint would only spin in
/// place: its joint becomes rigid (has_joint = false, joint_pruned = true, axis
/// and range cleared), so it merges into its parent's body (a jointed leaf's
/// component holds that leaf alone); its motor neuron is dropped, and so is its
/// proprioceptive sensor, which no longer sits on a joint. Pruning adds or
/// removes no sphere, so no sphere becomes a leaf: one pass suffices.
/// Sphere::body is left as grown; assemble_robot renumbers bodies.
/// Returns the number of joints pruned.
int prune_leaf_joints(GrownBody& body);

}  // namespace robozoo
