#pragma once
// The CPPN statistics of the paper's Figure 3, for one logged genome.
//
// Links are the expressed (enabled) link genes. A link is "forward" exactly as
// HyperNEAT (and robozoo's NEAT, docs/method.md section 2.2) defines it: the
// drawing position of its source is below that of its target. Those are the
// links the feed-forward regime may hold, "those that are possible in both
// regimes" in the paper's words; every other expressed link is "recurrent".
// Every link of a feed-forward CPPN is forward. Links on a directed cycle of the
// expressed network (self-loops included) are counted apart.
#include "robozoo/cppn_genome_t.hpp"

namespace robozoo {

struct GenotypeStats {
  double nodes = 0;            ///< node genes, inputs and outputs included (count)
  double hidden = 0;           ///< hidden nodes (count)
  double hidden_sigmoid = 0;   ///< hidden nodes with the signed sigmoid (activation 0) (count)
  double hidden_cosine = 0;    ///< hidden nodes with the signed cosine (activation 1) (count)
  double hidden_gaussian = 0;  ///< hidden nodes with the Gaussian (activation 2) (count)
  double hidden_other = 0;     ///< hidden nodes with another activation code (count)
  double link_genes = 0;       ///< link genes, disabled ones included (count)
  double links = 0;            ///< enabled links (count)
  double forward_links = 0;    ///< enabled links with position(from) < position(to) (count)
  double recurrent_links = 0;  ///< enabled links that are not forward (count)
  double cycle_links = 0;      ///< enabled links on a directed cycle, self-loops included (count)
};

/// Statistics of `g`. Throws std::invalid_argument for a link naming a node
/// the genome does not have, or for duplicate node ids.
GenotypeStats genotype_stats(const cppn_genome_t& g);

}  // namespace robozoo
