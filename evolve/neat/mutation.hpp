#pragma once
// NEAT mutations: add link, add node, weight perturbation.
#include <cstdint>

#include "evolve/core/rng.hpp"
#include "evolve/cppn/genome.hpp"
#include "evolve/neat/innovation.hpp"
#include "evolve/neat/params.hpp"

namespace robozoo {

/// Adds one new link gene with weight uniform in [-initial_weight_range,
/// initial_weight_range), born in `generation`. Up to p.add_link_tries random
/// (from, to) pairs are tried (from any node, to any non-input node); the first
/// legal one is taken. Legal: no gene from -> to exists yet (enabled or not),
/// and in the feed-forward regime from != to and the graph of all link genes,
/// disabled ones included, stays acyclic (so that no later re-enabling by
/// crossover can close a cycle either). Recurrent regime: self-loops and
/// cycles allowed. Returns false when no try found a legal link.
bool mutate_add_link(Genome& g, Regime regime, const GenomeLayout& layout, const NeatParams& p,
                     InnovationTracker& innov, int32_t generation, Rng& rng);

/// Splits an enabled link a -> b chosen uniformly: the link is disabled, a new
/// hidden node h gets an activation drawn uniformly from p.hidden_activations
/// (the first such split of the generation fixes it, see InnovationTracker),
/// a -> h has weight 1 and b's old weight goes to h -> b; both born in
/// `generation`. Returns false if g has no enabled link, or if g already has
/// the node this split would create. Throws std::invalid_argument if
/// p.hidden_activations names no valid activation.
bool mutate_add_node(Genome& g, const NeatParams& p, InnovationTracker& innov,
                     int32_t generation, Rng& rng);

/// Every link gene (enabled or not) younger than p.young_link_age generations
/// (generation - born < young_link_age) is perturbed; an older one with
/// probability p.old_link_perturb_probability. Perturbation: add uniform
/// [-weight_perturbation, weight_perturbation), clamp to [-weight_limit, weight_limit].
void mutate_weights(Genome& g, const NeatParams& p, int32_t generation, Rng& rng);

/// The mutation an offspring gets (the NEAT paper's order, one structural
/// change at most): with p.add_node_probability add a node; if none was added,
/// with p.add_link_probability add a link; if the structure did not change,
/// with p.mutate_weights_probability mutate the weights.
void mutate(Genome& g, Regime regime, const GenomeLayout& layout, const NeatParams& p,
            InnovationTracker& innov, int32_t generation, Rng& rng);

}  // namespace robozoo
