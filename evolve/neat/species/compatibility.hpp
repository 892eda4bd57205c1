#pragma once
// NEAT's compatibility distance.
#include "evolve/cppn/genome.hpp"
#include "evolve/neat/params.hpp"

namespace robozoo {

/// Link genes (enabled or not) are aligned by innovation, walking both sorted
/// lists together while both have genes left; Wbar is the mean absolute weight
/// difference of matching genes (0 when none match). Distance =
/// c_d * D / N + c_e * E / N + c_w * Wbar with N = 1 (HyperNEAT's setting).
/// CompatibilityRule::HyperNeat: D = unmatched genes met during that walk (it
/// stops at the end of the list that ends first), E = |#links(a) - #links(b)|.
/// Classic: D as before, E = the genes left after the walk (those beyond the
/// other genome's last innovation).
double compatibility_distance(const Genome& a, const Genome& b, const NeatParams& p);

}  // namespace robozoo
