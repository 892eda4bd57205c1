#include "study/analysis/report/paper_claims.hpp"

#include <cmath>

namespace robozoo {

const std::vector<PaperClaim>& paper_claims() {
  const double none = std::nan("");
  static const std::vector<PaperClaim> claims = {
      {"best_fitness",
       "recurrent fitter: p < 0.001 at generation 500 with 30 runs per regime, and over all 500 "
       "generations (Fig. 1)",
       1, true, 0.001, true},
      {"spheres", "recurrent slightly more, not significant", 0, false, none, true},
      {"leaves", "recurrent slightly more, not significant", 0, false, none, true},
      {"joints", "recurrent significantly fewer", -1, true, 0.05, true},
      {"distance_sensors", "recurrent significantly fewer", -1, true, 0.05, true},
      {"distance_per_sphere", "recurrent spheres significantly less likely to carry one", -1, true, 0.05, true},
      {"touch_per_sphere", "recurrent spheres significantly more likely to carry one", 1, true, 0.05, true},
      {"mean_radius", "nearly identical", 0, false, none, true},
      {"radius_variance", "similar", 0, false, none, true},
      {"max_depth", "not significantly different", 0, false, none, true},
      {"ground_spheres", "recurrent significantly fewer", -1, true, 0.05, true},
      {"ground_fraction", "recurrent significantly fewer", -1, true, 0.05, true},
      {"nodes", "recurrent fewer (no test reported)", -1, false, none, true},
      {"hidden", "recurrent fewer (no test reported)", -1, false, none, true},
      {"hidden_sigmoid", "recurrent fewer (no test reported)", -1, false, none, true},
      {"hidden_cosine", "recurrent fewer (no test reported)", -1, false, none, true},
      {"hidden_gaussian", "recurrent fewer (no test reported)", -1, false, none, true},
      {"links", "recurrent many more, \"not surprising\" since more links are possible (no test reported)", 1, false,
       none, true},
      {"forward_links", "recurrent significantly fewer", -1, true, 0.05, true},
      {"topology_changed_per_run",
       "96.99 % (recurrent) vs 59.92 % (feed-forward) of new champions, pooled over "
       "runs, p < 0.001",
       1, true, 0.001, false},
      {"improvement_changed_per_run",
       "0.559 (recurrent) vs 0.188 (feed-forward) per new champion, pooled, "
       "p < 0.001",
       1, true, 0.001, false},
      {"improvement_same_per_run", "0.255 (recurrent) vs 0.100 (feed-forward) per new champion, pooled, p < 0.05", 1,
       true, 0.05, false},
  };
  return claims;
}

const PaperClaim* paper_claim(const std::string& key) {
  for (const auto& c : paper_claims())
    if (c.key == key) return &c;
  return nullptr;
}

}  // namespace robozoo
