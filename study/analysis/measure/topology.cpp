#include "study/analysis/measure/topology.hpp"

#include <algorithm>
#include <vector>

#include "study/analysis/read/sphere_tree.hpp"

namespace robozoo {

std::string topology_code(const morphology_t& m, const TopologyOptions& options) {
  const SphereTree t = sphere_tree(m);
  const size_t n = t.parent.size();
  std::vector<std::string> code(n);
  // Children have larger indices than their parents: one backward pass.
  for (size_t k = n; k-- > 0;) {
    std::vector<std::string> kids;
    kids.reserve(t.children[k].size());
    for (int32_t c : t.children[k]) {
      const auto ci = static_cast<size_t>(c);
      kids.push_back((options.joints && m.spheres[ci].has_joint ? "j" : "") + code[ci]);
      code[ci].clear();
      code[ci].shrink_to_fit();
    }
    std::sort(kids.begin(), kids.end());
    std::string s = "(";
    for (const auto& c : kids) s += c;
    s += ")";
    code[k] = std::move(s);
  }
  return code[0];
}

bool same_topology(const morphology_t& a, const morphology_t& b, const TopologyOptions& options) {
  if (a.spheres.size() != b.spheres.size()) return false;
  return topology_code(a, options) == topology_code(b, options);
}

}  // namespace robozoo
