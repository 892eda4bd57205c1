#include "study/analysis/measure/morphology_stats.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "study/analysis/read/sphere_tree.hpp"

namespace robozoo {

MorphologyStats morphology_stats(const morphology_t& m, const std::vector<double>* min_center_z,
                                 const MorphologyStatsParams& params) {
  const SphereTree t = sphere_tree(m);
  const size_t n = t.parent.size();
  MorphologyStats s;
  s.spheres = static_cast<double>(n);
  long double sum_r = 0;
  for (size_t i = 0; i < n; ++i) {
    const sphere_t& sp = m.spheres[i];
    if (i > 0 && t.children[i].empty()) s.leaves += 1;
    if (sp.has_joint) s.joints += 1;
    if (sp.sensors & 1) s.distance_sensors += 1;
    if (sp.sensors & 2) s.touch_sensors += 1;
    if (sp.sensors & 4) s.proprio_sensors += 1;
    if (sp.sensors & 8) s.time_sensors += 1;
    s.max_depth = std::max(s.max_depth, static_cast<double>(t.depth[i]));
    sum_r += sp.radius;
  }
  const long double mean_r = sum_r / static_cast<long double>(n);
  long double ss = 0;
  for (const auto& sp : m.spheres) ss += (sp.radius - mean_r) * (sp.radius - mean_r);
  s.mean_radius = static_cast<double>(mean_r);
  s.radius_variance = static_cast<double>(ss / static_cast<long double>(n));
  if (min_center_z) {
    if (min_center_z->size() != n)
      throw std::invalid_argument("pose stream of genome " + std::to_string(m.genome_id) + " has " +
                                  std::to_string(min_center_z->size()) + " spheres, its morphology " +
                                  std::to_string(n));
    s.ground_known = true;
    for (size_t i = 0; i < n; ++i)
      if ((*min_center_z)[i] - m.spheres[i].radius <= params.ground_epsilon) s.ground_spheres += 1;
    s.ground_fraction = s.ground_spheres / s.spheres;
  }
  return s;
}

}  // namespace robozoo
