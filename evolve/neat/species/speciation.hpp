#pragma once
// Speciation with a dynamic compatibility threshold.
#include <cstdint>
#include <vector>

#include "evolve/cppn/genome.hpp"
#include "evolve/neat/params.hpp"
#include "evolve/neat/species/species.hpp"

namespace robozoo {

/// Assigns each genome, in order, to the first species (in the order of
/// `species`) whose representative is closer than `threshold`; a genome that
/// fits none founds a new species (id next_species_id++, age 0, representative
/// the genome, last_improvement `generation` (`generation` - 1 with StagnationRule::HyperNeat,
/// which counts the founding as the previous generation's improvement), best_fitness 0). Members lists
/// are rebuilt; species left without members are removed. Returns the species
/// id of each genome.
std::vector<int32_t> speciate(const std::vector<Genome>& genomes, std::vector<Species>& species, double threshold,
                              const NeatParams& p, int32_t& next_species_id, int32_t generation);

/// HyperNEAT raises a threshold below this to it before halving it (distance units).
constexpr double kHyperNeatThresholdFloor = 0.001;

/// The next threshold. ThresholdRule::Clamp: raised by p.compatibility_modifier when there are
/// more than p.target_species species, lowered by it (never below p.min_compatibility_threshold)
/// when there are fewer, kept otherwise. ThresholdRule::HyperNeat: see params.hpp (halved or
/// doubled near p.min_compatibility_threshold, else moved by the modifier).
double adjust_threshold(double threshold, int num_species, const NeatParams& p);

}  // namespace robozoo
