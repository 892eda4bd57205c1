#pragma once
// Fitness sharing and offspring allocation.
#include <cstdint>
#include <vector>

#include "evolve/neat/params.hpp"
#include "evolve/neat/species/species.hpp"

namespace robozoo {

/// True when a species has gone p.dropoff_age or more generations without improving.
bool is_stagnant(const Species& s, int32_t generation, const NeatParams& p);

/// Explicit fitness sharing: the sum over a species' members of fitness / size
/// (its mean raw fitness), times p.dropoff_factor when the species is stagnant.
double species_adjusted_fitness(const Species& s, const std::vector<double>& fitness, int32_t generation,
                                const NeatParams& p);

/// Splits `total` offspring among species in proportion to `shares`
/// (largest-remainder method: floors first, the rest one each in decreasing
/// order of the fractional parts, ties to the lower index). If every share is
/// zero, `fallback` (e.g. species sizes) is used instead. The counts always sum
/// to `total`. Throws std::invalid_argument for negative or non-finite shares,
/// mismatched sizes, or no positive weight at all.
std::vector<int> allocate_offspring(const std::vector<double>& shares, int total, const std::vector<double>& fallback);

/// Stanley's count_offspring (OffspringRounding::Skim). member_values[s][k]: the shared
/// fitness of member k of species s (raw fitness, times the drop-off factor when the species is
/// stagnant, divided by the species' size), species in population order, members in rank order.
/// Every member expects value / mean offspring, the mean taken over all members; walking the
/// species and their members in order, a member's whole part goes to its species at once and its
/// fractional part is added to a carry that runs across species; whenever the carry exceeds 1 its
/// whole part goes to the species of the member that made it do so. If the counts fall short of
/// `total`, the species with the most (the last of equals) gets one more, and if still short it
/// gets all `total` (Stanley's "population died"); counts above `total` (only by rounding error)
/// are taken from the largest. Throws std::invalid_argument when a value is negative or not
/// finite, or no value is positive.
std::vector<int> allocate_offspring_skim(const std::vector<std::vector<double>>& member_values, int total);

/// HyperNEAT's division (OffspringRounding::BestFirst): species i first gets
/// floor(shares[i] / sum * total) (nothing when every share is 0); the offspring left over go one
/// each to species_by_rank[0], species_by_rank[1], ... (the species of the population's genomes,
/// best raw fitness first), starting again at the front until none is left. The counts sum to
/// `total`. Throws std::invalid_argument for negative or non-finite shares, an empty ranking
/// while offspring are left over, or a rank naming no species.
std::vector<int> allocate_offspring_best_first(const std::vector<double>& shares, int total,
                                               const std::vector<size_t>& species_by_rank);

/// How many of a species' best members may reproduce:
/// floor(survival_threshold * size) + 1, at most size.
int num_parents(int species_size, const NeatParams& p);

}  // namespace robozoo
