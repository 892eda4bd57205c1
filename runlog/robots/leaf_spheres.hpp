#pragma once
// Which spheres of a robot are leaves: drawn red (all others blue) by
// robozoo-render and robozoo-view, as in the paper's Figure 4.
#include <vector>

#include "robozoo/morphology_t.hpp"

namespace robozoo {

/// Leaf spheres: those no other sphere names as its parent. A robot that is
/// just its root has one leaf.
std::vector<bool> leaf_spheres(const morphology_t& m);

}  // namespace robozoo
