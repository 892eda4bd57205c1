#pragma once
// NEAT's compatibility distance.
#include "evolve/cppn/genome.hpp"
#include "evolve/neat/params.hpp"

namespace robozoo {

/// Link genes are aligned by innovation (enabled or not). Genes of one genome
/// beyond the other's largest innovation are excess (E), other unmatched genes
/// disjoint (D); Wbar is the mean absolute weight difference of matching genes
/// (0 when none match). Distance = c_d * D / N + c_e * E / N + c_w * Wbar with
/// N = 1 (HyperNEAT's setting).
double compatibility_distance(const Genome& a, const Genome& b, const NeatParams& p);

}  // namespace robozoo
