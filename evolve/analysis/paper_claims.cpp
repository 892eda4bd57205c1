#include "evolve/analysis/paper_claims.hpp"

namespace robozoo {

const std::vector<PaperClaim>& paper_claims() {
  using G = ClaimGroup;
  static const std::vector<PaperClaim> claims = {
      {G::Fitness, "best_fitness", "recurrent significantly fitter at 500 generations (p < 0.001), and for all 500 (Fig. 1)", 1, true},
      {G::Morphology, "spheres", "recurrent slightly more, not significant", 0, false},
      {G::Morphology, "leaves", "recurrent slightly more, not significant", 0, false},
      {G::Morphology, "joints", "recurrent significantly fewer", -1, true},
      {G::Morphology, "distance_per_sphere", "recurrent spheres significantly less likely to carry one", -1, true},
      {G::Morphology, "touch_per_sphere", "recurrent spheres significantly more likely to carry one", 1, true},
      {G::Morphology, "proprio_sensors", "not discussed (Fig. 2)", 2, false},
      {G::Morphology, "time_sensors", "not discussed (Fig. 2)", 2, false},
      {G::Morphology, "mean_radius", "nearly identical", 0, false},
      {G::Morphology, "radius_variance", "similar", 0, false},
      {G::Morphology, "max_depth", "not significantly different", 0, false},
      {G::Morphology, "ground_spheres", "recurrent significantly fewer", -1, true},
      {G::Morphology, "ground_fraction", "recurrent significantly fewer", -1, true},
      {G::Genotype, "nodes", "recurrent fewer", -1, false},
      {G::Genotype, "hidden_sigmoid", "recurrent fewer", -1, false},
      {G::Genotype, "hidden_cosine", "recurrent fewer", -1, false},
      {G::Genotype, "hidden_gaussian", "recurrent fewer", -1, false},
      {G::Genotype, "links", "recurrent many more", 1, false},
      {G::Genotype, "forward_links", "recurrent significantly fewer", -1, true},
      {G::Champion, "topology_changed", "96.99 % (recurrent) vs 59.92 % (feed-forward), p < 0.001", 1, true},
      {G::Champion, "improvement_changed", "0.559 (recurrent) vs 0.188 (feed-forward), p < 0.001", 1, true},
      {G::Champion, "improvement_same", "0.255 (recurrent) vs 0.100 (feed-forward), p < 0.05", 1, true},
  };
  return claims;
}

}  // namespace robozoo
