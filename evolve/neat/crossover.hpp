#pragma once
// NEAT crossover, genes aligned by innovation.
#include "evolve/core/rng.hpp"
#include "evolve/cppn/genome.hpp"
#include "evolve/neat/params.hpp"

namespace robozoo {

/// Matching genes (same innovation) are copied whole (weight, enabled flag,
/// birth generation) from either parent with probability 1/2 each; disjoint and
/// excess genes come from the fitter parent (`a` when fitness_a >= fitness_b)
/// only, so the child has exactly the fitter parent's structure: its node genes
/// and the set of its link innovations. The child's id is -1 (the caller
/// assigns one). With p.disabled_gene_probability > 0 (classic NEAT), a gene
/// disabled in either parent is then inherited disabled with that probability
/// and enabled otherwise (one draw per such gene, in innovation order); with 0
/// no draw is made and the chosen gene is copied as it is (HyperNEAT).
Genome crossover(const Genome& a, double fitness_a, const Genome& b, double fitness_b,
                 const NeatParams& p, Rng& rng);
/// The same with disabled_gene_probability 0.
Genome crossover(const Genome& a, double fitness_a, const Genome& b, double fitness_b, Rng& rng);

}  // namespace robozoo
