#include "evolve/neat/species/speciation.hpp"

#include <algorithm>

#include "evolve/neat/species/compatibility.hpp"

namespace robozoo {

std::vector<int32_t> speciate(const std::vector<Genome>& genomes, std::vector<Species>& species, double threshold,
                              const NeatParams& p, int32_t& next_species_id, int32_t generation) {
  for (auto& s : species) s.members.clear();
  std::vector<int32_t> species_of(genomes.size(), -1);
  for (size_t i = 0; i < genomes.size(); ++i) {
    bool placed = false;
    for (auto& s : species) {
      if (compatibility_distance(s.representative, genomes[i], p) < threshold) {
        s.members.push_back(static_cast<int>(i));
        species_of[i] = s.id;
        placed = true;
        break;
      }
    }
    if (!placed) {
      Species s;
      s.id = next_species_id++;
      s.age = 0;
      // HyperNEAT counts a species' founding as an improvement one generation before it.
      s.last_improvement = p.stagnation == StagnationRule::HyperNeat ? generation - 1 : generation;
      s.best_fitness = 0.0;
      s.representative = genomes[i];
      s.members.push_back(static_cast<int>(i));
      species_of[i] = s.id;
      species.push_back(std::move(s));
    }
  }
  species.erase(std::remove_if(species.begin(), species.end(), [](const Species& s) { return s.members.empty(); }),
                species.end());
  return species_of;
}

double adjust_threshold(double threshold, int num_species, const NeatParams& p) {
  if (p.threshold_rule == ThresholdRule::HyperNeat) {
    const double m = num_species < p.target_species   ? -p.compatibility_modifier
                     : num_species > p.target_species ? p.compatibility_modifier
                                                      : 0.0;
    const double floor = p.min_compatibility_threshold;
    if (m < 0.0 && threshold < -m + floor) return std::max(threshold, kHyperNeatThresholdFloor) / 2.0;
    if (threshold < m + floor) return threshold * 2.0;
    return threshold + m;
  }
  if (num_species > p.target_species) return threshold + p.compatibility_modifier;
  if (num_species < p.target_species)
    return std::max(p.min_compatibility_threshold, threshold - p.compatibility_modifier);
  return threshold;
}

}  // namespace robozoo
