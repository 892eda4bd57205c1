#include "evolve/neat/xor/xor_presets.hpp"

#include <stdexcept>

#include "evolve/neat/xor/xor_task.hpp"

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
    // The NEAT paper's check keeps robozoo's earlier mechanics under the Stanley options below.
    apply_neat_mechanics(p, NeatMechanics::Robozoo);
    p.hidden_activations = x.sigmoid_only;
    p.excess_coefficient = 1.0;
    p.disjoint_coefficient = 1.0;
    p.weight_coefficient = 0.4;
    p.compatibility_threshold = 3.0;
    p.compatibility_modifier = 0.0;  // the paper's threshold is fixed
    p.add_node = AddNodeRule::Classic;
    p.add_node_innovations = AddNodeInnovations::Shared;  // NEAT's innovation list
    p.disabled_gene_probability = 0.75;
    p.interspecies_mating_probability = 0.001;
    p.initial_links = InitialLinks::InputsToOutputs;
    p.link_rule = LinkRule::CycleTest;
    p.add_link = AddLinkRule::Tries;
    p.compatibility = CompatibilityRule::Classic;
    p.self_loops = true;  // classic NEAT's recurrent networks may loop on a node
    // Where the paper is silent or summarises, Stanley's own NEAT C++ (NEAT 1.2.1, the code
    // behind the paper's figures; his XOR parameter files p2nv.ne / test.ne):
    // - weights: start uniform in [-1, 1] (Population::spawn), new links the same
    //   (mutate_add_link), his mutate_link_weights (the paper's "90 % perturbed, 10 % new value"
    //   in his code: severe calls, a stronger tail, power 2.5), clamped to [-8, 8]; the paper's
    //   80 % of offspring get it (his files say 0.9);
    p.initial_weight_range = 1.0;
    p.weight_limit = 8.0;
    p.weight_perturbation = 2.5;
    p.weight_mutation = WeightMutationRule::Stanley;
    // - mating: mate_multipoint 0.6 / mate_multipoint_avg 0.4, mate_only_prob 0.2, mom and dad
    //   drawn independently, his enabled-flag and tie rules;
    p.crossover_rule = CrossoverRule::Stanley;
    p.mate_average_probability = 0.4;
    p.mate_only_probability = 0.2;
    p.independent_parents = true;
    // - mutation: the add-node / add-link draw decides, and add-node never splits a bias link;
    p.structural_draw_decides = true;
    p.split_bias_links = false;
    // - species: no generation-champion copy, a species' champion cloned with more than 5
    //   offspring, his stagnation test with fitness x 0.01 (dropoff_age 15), offspring by carried
    //   fractions, delta coding after dropoff_age + 5 = 20 generations without a population
    //   record, childless species kept as speciation candidates.
    p.keep_generation_champion = false;
    p.species_elitism_min_offspring = 6;
    p.stagnation = StagnationRule::Stanley;
    p.dropoff_age = 15;
    p.dropoff_factor = 0.01;
    p.offspring_rounding = OffspringRounding::Skim;
    p.population_stagnation_generations = p.dropoff_age + 5;
    p.childless_species_stay = true;
    // - evaluation (xor_evaluate, Network::activate): unreached nodes output 0, networks relaxed,
    //   0.5 counts as 1; evaluations counted up to the winner.
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
