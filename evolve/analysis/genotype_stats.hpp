#pragma once
// The CPPN statistics of the paper's Figure 3, for one logged genome.
//
// Links are the expressed (enabled) link genes. A link is "forward" when it lies
// on no directed cycle of the expressed network (self-loops are cycles): the
// links that the feed-forward regime could hold as they are, "those that are
// possible in both regimes" in the paper's words. Every link of a feed-forward
// CPPN is forward.
#include "robozoo/genome_t.hpp"

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
  double forward_links = 0;    ///< enabled links on no directed cycle (count)
  double recurrent_links = 0;  ///< enabled links on a directed cycle, self-loops included (count)
};

/// Statistics of `g`. Throws std::invalid_argument for a link naming a node
/// the genome does not have, or for duplicate node ids.
GenotypeStats genotype_stats(const genome_t& g);

}  // namespace robozoo
