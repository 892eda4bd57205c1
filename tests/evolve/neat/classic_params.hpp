#pragma once
// NEAT parameters with the classic NEAT topology rules that robozoo used before
// it followed HyperNEAT's: inputs-to-outputs start, the cycle test, add-link by
// tries, self-loops allowed in the recurrent regime, add-node that disables the
// split link, classic excess counting; and robozoo's earlier mechanics
// (NeatMechanics::Robozoo: crossover from the fitter parent, one structural
// mutation, the champion as representative, ...). Tests of those options use it.
#include "evolve/neat/params.hpp"

namespace robozoo {

inline NeatParams classic_neat() {
  NeatParams p;
  apply_neat_mechanics(p, NeatMechanics::Robozoo);
  p.initial_links = InitialLinks::InputsToOutputs;
  p.link_rule = LinkRule::CycleTest;
  p.add_link = AddLinkRule::Tries;
  p.self_loops = true;
  p.add_node = AddNodeRule::Classic;
  p.add_node_innovations = AddNodeInnovations::Shared;
  p.compatibility = CompatibilityRule::Classic;
  return p;
}

}  // namespace robozoo
