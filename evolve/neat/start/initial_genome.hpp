#pragma once
// Generation-0 genomes (HyperNEAT's default start; docs/method.md, "CPPN-NEAT").
#include <cstdint>

#include "evolve/core/rng.hpp"
#include "evolve/cppn/genome.hpp"
#include "evolve/neat/params.hpp"

namespace robozoo {

/// Innovation number of the initial link from fixed node `from` (an input or an
/// output: 0 .. num_inputs + num_outputs - 1) to output index `output` (0-based
/// among the outputs): from * num_outputs + output. The same in every genome of
/// every run with this layout, whichever regime.
int64_t initial_link_innovation(const GenomeLayout& layout, int from, int output);
/// First innovation number free for mutations: (num_inputs + num_outputs) * num_outputs.
int64_t first_free_innovation(const GenomeLayout& layout);

/// Whether the regime allows a link from -> to in g under p's rules, judged by
/// the nodes' drawing positions and the self-loop setting alone (no test of
/// existing links; the cycle test of LinkRule::CycleTest is mutate_add_link's).
/// Never a link into an input.
bool link_allowed_by_positions(const NodeGene& from, const NodeGene& to, Regime regime, const NeatParams& p);

/// A generation-0 genome: the inputs (Linear, position 0), the outputs
/// (layout.output_activation, position 1), no hidden node, and its links, born
/// in generation 0 with weights uniform in [-initial_weight_range,
/// initial_weight_range), drawn in innovation order:
/// - p.initial_links == AllAllowed (HyperNEAT's createTopology, edge density 1):
///   a link from every node to every non-input node the regime allows: in the
///   feed-forward regime every input to every output (99 links for the robot
///   layout); in the recurrent regime also every output to every other output
///   (+110: 209), and to itself when p.self_loops (+11).
/// - InputsToOutputs: every input to every output only, whichever regime.
/// - AllAllowedRecurrentZero: AllAllowed's links, every weight drawn as AllAllowed
///   draws it (the same genome for the same rng state), then every link out of an
///   output (output -> output, self-loops included) set to exactly 0. In the
///   recurrent regime: 209 links, the 110 recurrent ones at 0, so the CPPN computes
///   what its 99 input links alone compute until a mutation moves a zero weight.
///   In the feed-forward regime it is AllAllowed (99 links, none from an output).
/// Throws std::invalid_argument for a layout without inputs or outputs.
Genome initial_genome(const GenomeLayout& layout, int64_t id, const NeatParams& p, Regime regime, Rng& rng);

}  // namespace robozoo
