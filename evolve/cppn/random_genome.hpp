#pragma once
// Random valid CPPN genomes, for tests and benchmarks (before and beside NEAT).
#include "evolve/core/rng.hpp"
#include "evolve/cppn/genome.hpp"

namespace robozoo {

/// A random genome that passes validate_genome(g, layout):
/// - every input (bias included) linked to every output, weights uniform in [-3, 3)
///   (HyperNEAT's fully connected start), innovations 0, 1, ... in (input, output) order;
/// - `hidden_nodes` hidden nodes (ids from layout.first_hidden()), hidden node k
///   (0-based) at drawing position (k + 1) / (hidden_nodes + 1), each with an
///   activation drawn from codes 0-2 (signed sigmoid, signed cosine, Gaussian), one
///   link into it from a random input or earlier hidden node and one link out of it
///   to a random output;
/// - up to `extra_links` further links between random distinct (from, to) pairs not
///   yet linked (fewer only when no such pair is left).
/// With recurrent = false every link goes forward in the order inputs < hidden nodes
/// (by id) < outputs, so the genome is acyclic; with recurrent = true any non-input
/// node may receive a link from any node, itself included (cycles and self-loops).
/// Weights of hidden and extra links are uniform in [-3, 3); ids, innovations and
/// weights depend only on the arguments and the generator's state.
/// Throws std::invalid_argument if hidden_nodes or extra_links is negative.
Genome random_cppn(const GenomeLayout& layout, bool recurrent, int hidden_nodes, int extra_links, Rng& rng);

}  // namespace robozoo
