#include "evolve/neat/xor_presets.hpp"

#include <stdexcept>

#include "evolve/neat/xor_task.hpp"

namespace robozoo {
namespace {

constexpr uint32_t bit(Activation a) { return 1u << static_cast<int>(a); }

}  // namespace

std::vector<std::string> xor_preset_names() { return {"default", "neat-paper"}; }

XorPreset xor_preset(const std::string& name) {
  XorPreset x;
  x.name = name;
  if (name == "default") {
    x.layout = xor_layout(Activation::SignedSigmoid);
    x.sigmoid_only = bit(Activation::SignedSigmoid);
    x.all_three = bit(Activation::SignedSigmoid) | bit(Activation::SignedCosine) | bit(Activation::Gaussian);
    x.params.hidden_activations = x.all_three;
    return x;
  }
  if (name == "neat-paper") {
    x.layout = xor_layout(Activation::SteepenedSigmoid);
    x.sigmoid_only = bit(Activation::SteepenedSigmoid);
    x.all_three = bit(Activation::SteepenedSigmoid) | bit(Activation::SignedCosine) | bit(Activation::Gaussian);
    NeatParams& p = x.params;
    p.hidden_activations = x.sigmoid_only;
    p.excess_coefficient = 1.0;
    p.disjoint_coefficient = 1.0;
    p.weight_coefficient = 0.4;
    p.compatibility_threshold = 3.0;
    p.compatibility_modifier = 0.0;  // the paper's threshold is fixed
    p.add_node = AddNodeRule::Classic;
    p.disabled_gene_probability = 0.75;
    // Each weight 90 % perturbed, 10 % given a new random value, when weights mutate (80 %).
    p.weight_mutation = WeightMutationRule::Classic;
    p.weight_replace_probability = 0.1;
    p.interspecies_mating_probability = 0.001;
    p.initial_links = InitialLinks::InputsToOutputs;
    p.link_rule = LinkRule::CycleTest;
    p.add_link = AddLinkRule::Tries;
    p.compatibility = CompatibilityRule::Classic;
    p.self_loops = true;  // classic NEAT's recurrent networks may loop on a node
    // Stanley's NEAT C++ (xor_evaluate, Network::activate): unreached nodes output 0, networks
    // relaxed, 0.5 counts as 1; evaluations counted up to the winner.
    x.rules.stanley_activation = true;
    x.rules.half_is_one = true;
    x.count_to_solver = true;
    return x;
  }
  std::string names;
  for (const auto& n : xor_preset_names()) names += (names.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown XOR preset '" + name + "' (use " + names + ")");
}

}  // namespace robozoo
