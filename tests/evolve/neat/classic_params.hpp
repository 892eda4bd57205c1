#pragma once
// NEAT parameters with the classic NEAT topology rules that robozoo used before
// it followed HyperNEAT's: inputs-to-outputs start, the cycle test, add-link by
// tries, self-loops allowed in the recurrent regime, add-node that disables the
// split link, classic excess counting. Tests of those options use it.
#include "evolve/neat/params.hpp"

namespace robozoo {

inline NeatParams classic_neat() {
  NeatParams p;
  p.initial_links = InitialLinks::InputsToOutputs;
  p.link_rule = LinkRule::CycleTest;
  p.add_link = AddLinkRule::Tries;
  p.self_loops = true;
  p.add_node = AddNodeRule::Classic;
  p.compatibility = CompatibilityRule::Classic;
  return p;
}

}  // namespace robozoo
