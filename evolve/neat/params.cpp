#include "evolve/neat/params.hpp"

#include <stdexcept>

namespace robozoo {
namespace {

template <class E>
E from_name(const std::string& s, std::initializer_list<E> all, std::string (*name)(E), const char* what) {
  std::string names;
  for (E e : all) {
    if (name(e) == s) return e;
    names += (names.empty() ? "" : ", ") + name(e);
  }
  throw std::invalid_argument("unknown " + std::string(what) + " '" + s + "' (use " + names + ")");
}

}  // namespace

std::string link_rule_name(LinkRule r) { return r == LinkRule::Positions ? "positions" : "cycle_test"; }
std::string initial_links_name(InitialLinks r) {
  switch (r) {
    case InitialLinks::AllAllowed: return "all_allowed";
    case InitialLinks::InputsToOutputs: return "inputs_to_outputs";
    case InitialLinks::AllAllowedRecurrentZero: return "all_allowed_recurrent_zero";
  }
  return "unknown";
}
std::string add_link_rule_name(AddLinkRule r) { return r == AddLinkRule::Uniform ? "uniform" : "tries"; }
std::string add_node_rule_name(AddNodeRule r) { return r == AddNodeRule::HyperNeat ? "hyperneat" : "classic"; }
std::string add_node_innovations_name(AddNodeInnovations r) {
  return r == AddNodeInnovations::Fresh ? "fresh" : "shared";
}
std::string compatibility_rule_name(CompatibilityRule r) {
  return r == CompatibilityRule::HyperNeat ? "hyperneat" : "classic";
}

std::string weight_mutation_rule_name(WeightMutationRule r) {
  switch (r) {
    case WeightMutationRule::HyperNeat: return "hyperneat";
    case WeightMutationRule::Classic: return "classic";
    case WeightMutationRule::Stanley: return "stanley";
  }
  return "unknown";
}
std::string crossover_rule_name(CrossoverRule r) { return r == CrossoverRule::Robozoo ? "robozoo" : "stanley"; }
std::string stagnation_rule_name(StagnationRule r) {
  switch (r) {
    case StagnationRule::Robozoo: return "robozoo";
    case StagnationRule::Stanley: return "stanley";
    case StagnationRule::HyperNeat: return "hyperneat";
  }
  return "unknown";
}
std::string offspring_rounding_name(OffspringRounding r) {
  switch (r) {
    case OffspringRounding::LargestRemainder: return "largest_remainder";
    case OffspringRounding::Skim: return "skim";
    case OffspringRounding::BestFirst: return "best_first";
  }
  return "unknown";
}
std::string crossover_genes_name(CrossoverGenes r) {
  switch (r) {
    case CrossoverGenes::Fitter: return "fitter";
    case CrossoverGenes::Both: return "both";
    case CrossoverGenes::Drawn: return "drawn";
  }
  return "unknown";
}
std::string mutation_order_name(MutationOrder r) {
  return r == MutationOrder::OneStructural ? "one_structural" : "independent";
}
std::string representative_name(Representative r) { return r == Representative::Champion ? "champion" : "best_ever"; }
std::string threshold_rule_name(ThresholdRule r) { return r == ThresholdRule::Clamp ? "clamp" : "hyperneat"; }
std::string neat_mechanics_name(NeatMechanics m) { return m == NeatMechanics::HyperNeat ? "hyperneat" : "robozoo"; }

LinkRule link_rule_from_name(const std::string& s) {
  return from_name(s, {LinkRule::Positions, LinkRule::CycleTest}, link_rule_name, "link rule");
}
InitialLinks initial_links_from_name(const std::string& s) {
  return from_name(s, {InitialLinks::AllAllowed, InitialLinks::InputsToOutputs, InitialLinks::AllAllowedRecurrentZero},
                   initial_links_name, "initial links");
}
AddLinkRule add_link_rule_from_name(const std::string& s) {
  return from_name(s, {AddLinkRule::Uniform, AddLinkRule::Tries}, add_link_rule_name, "add-link rule");
}
AddNodeRule add_node_rule_from_name(const std::string& s) {
  return from_name(s, {AddNodeRule::HyperNeat, AddNodeRule::Classic}, add_node_rule_name, "add-node rule");
}
AddNodeInnovations add_node_innovations_from_name(const std::string& s) {
  return from_name(s, {AddNodeInnovations::Fresh, AddNodeInnovations::Shared}, add_node_innovations_name,
                   "add-node innovations");
}
CompatibilityRule compatibility_rule_from_name(const std::string& s) {
  return from_name(s, {CompatibilityRule::HyperNeat, CompatibilityRule::Classic}, compatibility_rule_name,
                   "compatibility rule");
}

WeightMutationRule weight_mutation_rule_from_name(const std::string& s) {
  return from_name(s, {WeightMutationRule::HyperNeat, WeightMutationRule::Classic, WeightMutationRule::Stanley},
                   weight_mutation_rule_name, "weight-mutation rule");
}
CrossoverRule crossover_rule_from_name(const std::string& s) {
  return from_name(s, {CrossoverRule::Robozoo, CrossoverRule::Stanley}, crossover_rule_name, "crossover rule");
}
StagnationRule stagnation_rule_from_name(const std::string& s) {
  return from_name(s, {StagnationRule::Robozoo, StagnationRule::Stanley, StagnationRule::HyperNeat},
                   stagnation_rule_name, "stagnation rule");
}
OffspringRounding offspring_rounding_from_name(const std::string& s) {
  return from_name(s, {OffspringRounding::LargestRemainder, OffspringRounding::Skim, OffspringRounding::BestFirst},
                   offspring_rounding_name, "offspring rounding");
}
CrossoverGenes crossover_genes_from_name(const std::string& s) {
  return from_name(s, {CrossoverGenes::Fitter, CrossoverGenes::Both, CrossoverGenes::Drawn}, crossover_genes_name,
                   "crossover genes");
}
MutationOrder mutation_order_from_name(const std::string& s) {
  return from_name(s, {MutationOrder::OneStructural, MutationOrder::Independent}, mutation_order_name,
                   "mutation order");
}
Representative representative_from_name(const std::string& s) {
  return from_name(s, {Representative::Champion, Representative::BestEver}, representative_name, "representative");
}
ThresholdRule threshold_rule_from_name(const std::string& s) {
  return from_name(s, {ThresholdRule::Clamp, ThresholdRule::HyperNeat}, threshold_rule_name, "threshold rule");
}
NeatMechanics neat_mechanics_from_name(const std::string& s) {
  return from_name(s, {NeatMechanics::HyperNeat, NeatMechanics::Robozoo}, neat_mechanics_name, "NEAT mechanics");
}

void apply_neat_mechanics(NeatParams& p, NeatMechanics m) {
  const bool h = m == NeatMechanics::HyperNeat;
  p.crossover_genes = h ? CrossoverGenes::Drawn : CrossoverGenes::Fitter;
  p.mutation_order = h ? MutationOrder::Independent : MutationOrder::OneStructural;
  p.representative = h ? Representative::BestEver : Representative::Champion;
  p.threshold_rule = h ? ThresholdRule::HyperNeat : ThresholdRule::Clamp;
  p.stagnation = h ? StagnationRule::HyperNeat : StagnationRule::Robozoo;
  p.offspring_rounding = h ? OffspringRounding::BestFirst : OffspringRounding::LargestRemainder;
  p.childless_species_stay = h;
  p.interspecies_mating_probability = h ? 0.0 : 0.001;
}

std::string neat_mechanics_of(const NeatParams& p) {
  for (NeatMechanics m : {NeatMechanics::HyperNeat, NeatMechanics::Robozoo}) {
    NeatParams q = p;
    apply_neat_mechanics(q, m);
    if (q.crossover_genes == p.crossover_genes && q.mutation_order == p.mutation_order &&
        q.representative == p.representative && q.threshold_rule == p.threshold_rule && q.stagnation == p.stagnation &&
        q.offspring_rounding == p.offspring_rounding && q.childless_species_stay == p.childless_species_stay &&
        q.interspecies_mating_probability == p.interspecies_mating_probability)
      return neat_mechanics_name(m);
  }
  return "custom";
}

}  // namespace robozoo
