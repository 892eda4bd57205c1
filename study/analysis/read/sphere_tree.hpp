#pragma once
// The sphere tree of a logged robot (morphology_t.spheres[].parent), checked:
// a log is never trusted. Growth adds a sphere after its parent, so sphere 0 is
// the root (parent -1) and every other sphere's parent has a smaller index.
#include <cstdint>
#include <vector>

#include "robozoo/morphology_t.hpp"

namespace robozoo {

struct SphereTree {
  std::vector<int32_t> parent;                 ///< parent index per sphere, -1 for the root
  std::vector<std::vector<int32_t>> children;  ///< child indices per sphere, in growth order
  std::vector<int32_t> depth;                  ///< spheres between a sphere and the root (root 0)
};

/// Builds the tree of `m`; throws std::invalid_argument naming the sphere when
/// the parents do not form a tree in growth order (or there is no sphere).
SphereTree sphere_tree(const morphology_t& m);

}  // namespace robozoo
