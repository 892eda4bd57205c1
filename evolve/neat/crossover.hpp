#pragma once
// NEAT crossover, genes aligned by innovation.
#include "evolve/core/rng.hpp"
#include "evolve/cppn/genome.hpp"

namespace robozoo {

/// Matching genes (same innovation) are copied whole (weight, enabled flag,
/// birth generation) from either parent with probability 1/2 each; disjoint and
/// excess genes come from the fitter parent (`a` when fitness_a >= fitness_b)
/// only, so the child has exactly the fitter parent's structure: its node genes
/// and the set of its link innovations. The child's id is -1 (the caller
/// assigns one).
Genome crossover(const Genome& a, double fitness_a, const Genome& b, double fitness_b, Rng& rng);

}  // namespace robozoo
