#include "evolve/neat/params.hpp"

#include <stdexcept>

namespace robozoo {
namespace {

template <class E>
E from_name(const std::string& s, std::initializer_list<E> all, std::string (*name)(E),
            const char* what) {
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
  return r == StagnationRule::HyperNeat ? "hyperneat" : "stanley";
}
std::string offspring_rounding_name(OffspringRounding r) {
  return r == OffspringRounding::LargestRemainder ? "largest_remainder" : "skim";
}

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
  return from_name(s, {StagnationRule::HyperNeat, StagnationRule::Stanley}, stagnation_rule_name,
                   "stagnation rule");
}
OffspringRounding offspring_rounding_from_name(const std::string& s) {
  return from_name(s, {OffspringRounding::LargestRemainder, OffspringRounding::Skim}, offspring_rounding_name,
                   "offspring rounding");
}

}  // namespace robozoo
