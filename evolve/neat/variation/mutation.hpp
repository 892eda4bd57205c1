#pragma once
// NEAT mutations: add link, add node, weight perturbation.
#include <cstdint>

#include "evolve/core/rng.hpp"
#include "evolve/cppn/genome.hpp"
#include "evolve/neat/variation/innovation.hpp"
#include "evolve/neat/params.hpp"

namespace robozoo {

/// Whether the regime allows a new link from -> to in g: never into an input;
/// a self-loop only in the recurrent regime with p.self_loops; otherwise any
/// link in the recurrent regime; in the feed-forward regime a forward link
/// (pos(from) < pos(to)) with LinkRule::Positions, or a link that closes no
/// directed cycle over all link genes, disabled ones included, with
/// LinkRule::CycleTest (so no later re-enabling can close one either).
/// Existing genes are not looked at otherwise.
bool link_allowed(const Genome& g, const NodeGene& from, const NodeGene& to, Regime regime, const NeatParams& p);

/// Adds one new link gene with weight uniform in [-initial_weight_range,
/// initial_weight_range), born in `generation`, between two nodes that have no
/// gene from -> to yet (enabled or not) and that link_allowed allows.
/// AddLinkRule::Uniform (HyperNEAT): one uniform draw among all such pairs,
/// listed in (from, to) node order; fails only when there is none.
/// AddLinkRule::Tries: up to p.add_link_tries random (from any node, to any
/// non-input node) pairs, the first allowed one. Returns false when no link was added.
bool mutate_add_link(Genome& g, Regime regime, const GenomeLayout& layout, const NeatParams& p,
                     InnovationTracker& innov, int32_t generation, Rng& rng);

/// Splits a link a -> b chosen uniformly among the enabled links other than
/// self-loops; with AddNodeRule::HyperNeat among the enabled *forward* links
/// only; without p.split_bias_links never a link from the bias input (Stanley's
/// 20 random tries among all link genes, taken as the uniform choice among those
/// they may accept). A new hidden node h, at the mean of a's and b's drawing positions,
/// gets an activation drawn uniformly from p.hidden_activations. Its numbers:
/// with AddNodeInnovations::Fresh (HyperNEAT) a new node id and new link
/// innovations for every split; with Shared the first split of a link in the
/// generation fixes node id, innovations and activation for every later
/// split of that link (see InnovationTracker). a -> h gets weight
/// 1. HyperNeat: the old link stays enabled with its weight halved (w/2) and
/// is born again in `generation`, h -> b gets w/4. Classic: the old link is
/// disabled, h -> b gets w. New links are born in `generation`. Returns false
/// if no link can be split, or if g already has the node this split would
/// create. Throws std::invalid_argument if p.hidden_activations names no valid activation.
bool mutate_add_node(Genome& g, const NeatParams& p, InnovationTracker& innov, int32_t generation, Rng& rng);

/// Stanley's weight mutation: the probability that one call is "severe".
inline constexpr double kStanleySevereProbability = 0.5;

/// WeightMutationRule::HyperNeat: every link gene (enabled or not) younger than
/// p.young_link_age generations (generation - born < young_link_age) is
/// perturbed; an older one with probability p.old_link_perturb_probability.
/// Classic (the NEAT paper): every link gene, replaced by a new value uniform in
/// [-initial_weight_range, initial_weight_range) with probability
/// p.weight_replace_probability, else perturbed. Perturbation: add uniform
/// [-weight_perturbation, weight_perturbation); then clamp to [-weight_limit, weight_limit].
/// Stanley (his NEAT C++): one draw decides whether the call is severe (probability
/// kStanleySevereProbability); then per link gene, in innovation order, a perturbation d
/// uniform in [-weight_perturbation, weight_perturbation) and, for a severe call or a link in
/// the tail (at least 10 genes, index > 0.8 x count), a draw u: w += d when u > 0.3 (severe) /
/// 0.5 (tail), w = d when u > 0.1 / 0.3, else w kept; any other link w += d. Then clamp.
void mutate_weights(Genome& g, const NeatParams& p, int32_t generation, Rng& rng);

/// The mutation an offspring gets. With p.mutation_order == MutationOrder::Independent
/// (HyperNEAT's testMutate): with p.add_node_probability add a node, then with
/// p.add_link_probability add a link, then with p.mutate_weights_probability mutate the weights
/// (three draws, always all made; new links are young, so weights mutated after a structural
/// change perturb them too). With MutationOrder::OneStructural (the NEAT paper's order, one
/// structural change at most): with p.add_node_probability add a node; if none was added,
/// with p.add_link_probability add a link; if the structure did not change,
/// with p.mutate_weights_probability mutate the weights. With
/// p.structural_draw_decides (Stanley), an add-node or add-link whose draw
/// succeeded ends the mutation even when it found nothing to add.
void mutate(Genome& g, Regime regime, const GenomeLayout& layout, const NeatParams& p, InnovationTracker& innov,
            int32_t generation, Rng& rng);

}  // namespace robozoo
