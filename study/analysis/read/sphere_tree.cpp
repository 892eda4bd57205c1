#include "study/analysis/read/sphere_tree.hpp"

#include <stdexcept>
#include <string>

namespace robozoo {

SphereTree sphere_tree(const morphology_t& m) {
  const size_t n = m.spheres.size();
  if (n == 0) throw std::invalid_argument("morphology of genome " + std::to_string(m.genome_id) + " has no sphere");
  SphereTree t;
  t.parent.resize(n);
  t.children.resize(n);
  t.depth.assign(n, 0);
  for (size_t i = 0; i < n; ++i) {
    const int32_t p = m.spheres[i].parent;
    const bool ok = i == 0 ? p == -1 : (p >= 0 && static_cast<size_t>(p) < i);
    if (!ok)
      throw std::invalid_argument("morphology of genome " + std::to_string(m.genome_id) + ": sphere " +
                                  std::to_string(i) + " has parent " + std::to_string(p) +
                                  (i == 0 ? " (the root's must be -1)" : " (must be an earlier sphere)"));
    t.parent[i] = p;
    if (i > 0) {
      t.children[static_cast<size_t>(p)].push_back(static_cast<int32_t>(i));
      t.depth[i] = t.depth[static_cast<size_t>(p)] + 1;
    }
  }
  return t;
}

}  // namespace robozoo
