#include "runlog/robots/leaf_spheres.hpp"

namespace robozoo {

std::vector<bool> leaf_spheres(const morphology_t& m) {
  std::vector<bool> leaf(m.spheres.size(), true);
  for (const sphere_t& s : m.spheres)
    if (s.parent >= 0 && static_cast<size_t>(s.parent) < leaf.size()) leaf[static_cast<size_t>(s.parent)] = false;
  return leaf;
}

}  // namespace robozoo
