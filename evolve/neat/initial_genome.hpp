#pragma once
// Generation-0 genomes (HyperNEAT's default start, DESIGN.md section 2).
#include <cstdint>

#include "evolve/core/rng.hpp"
#include "evolve/cppn/genome.hpp"
#include "evolve/neat/params.hpp"

namespace robozoo {

/// Innovation number of the initial link from input `input` to output index
/// `output` (0-based among the outputs): input * num_outputs + output. The same
/// in every genome of every run with this layout.
int64_t initial_link_innovation(const GenomeLayout& layout, int input, int output);
/// First innovation number free for mutations: num_inputs * num_outputs.
int64_t first_free_innovation(const GenomeLayout& layout);

/// Every input (the bias included) linked to every output, weights uniform in
/// [-initial_weight_range, initial_weight_range), no hidden node, links born in
/// generation 0. Input nodes are Linear (they only hold their value), outputs
/// have layout.output_activation. Throws std::invalid_argument for a layout
/// without inputs or outputs.
Genome initial_genome(const GenomeLayout& layout, int64_t id, const NeatParams& p, Rng& rng);

}  // namespace robozoo
