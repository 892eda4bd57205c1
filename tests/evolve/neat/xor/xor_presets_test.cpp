#include "evolve/neat/xor/xor_presets.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "evolve/config/run_config.hpp"
#include "evolve/neat/population.hpp"
#include "evolve/neat/xor/xor_task.hpp"

namespace robozoo {
namespace {

TEST(XorPresets, NeatPaperPresetHasThePapersParameters) {
  const XorPreset x = xor_preset("neat-paper");
  const NeatParams& p = x.params;
  EXPECT_EQ(x.layout.output_activation, Activation::SteepenedSigmoid);
  EXPECT_EQ(p.hidden_activations, 1u << static_cast<int>(Activation::SteepenedSigmoid));
  EXPECT_EQ(p.excess_coefficient, 1.0);
  EXPECT_EQ(p.disjoint_coefficient, 1.0);
  EXPECT_EQ(p.weight_coefficient, 0.4);
  EXPECT_EQ(p.compatibility_threshold, 3.0);
  EXPECT_EQ(p.compatibility_modifier, 0.0);
  EXPECT_EQ(p.add_node, AddNodeRule::Classic);
  EXPECT_EQ(p.disabled_gene_probability, 0.75);
  EXPECT_EQ(p.interspecies_mating_probability, 0.001);
  EXPECT_EQ(p.initial_links, InitialLinks::InputsToOutputs);
  EXPECT_EQ(p.compatibility, CompatibilityRule::Classic);
  validate_neat_params(p);
  const XorPreset d = xor_preset("default");
  EXPECT_EQ(d.params.add_node, AddNodeRule::HyperNeat);
  EXPECT_EQ(d.layout.output_activation, Activation::SignedSigmoid);
  EXPECT_THROW(xor_preset("neat"), std::invalid_argument);
}

TEST(XorPresets, SteepenedOutputIsReadAsItIs) {
  // One link bias -> output of weight w: output 1 / (1 + e^(-4.9 w)) on every pattern.
  const XorPreset x = xor_preset("neat-paper");
  Genome g;
  g.id = 0;
  g.nodes = {{0, NodeKind::Input, Activation::Linear, 0.0},
             {1, NodeKind::Input, Activation::Linear, 0.0},
             {2, NodeKind::Bias, Activation::Linear, 0.0},
             {3, NodeKind::Output, Activation::SteepenedSigmoid, 1.0}};
  g.links = {{0, 2, 3, 0.5, true, 0}};
  const XorResult r = evaluate_xor(g, x.layout);
  const double y = 1.0 / (1.0 + std::exp(-4.9 * 0.5));
  for (double out : r.outputs) EXPECT_DOUBLE_EQ(out, y);
  EXPECT_FALSE(r.solved);
  EXPECT_DOUBLE_EQ(r.fitness, (4 - (2 * y + 2 * (1 - y))) * (4 - (2 * y + 2 * (1 - y))));
  EXPECT_THROW(evaluate_xor(g, xor_layout(Activation::Gaussian)), std::invalid_argument);
}

TEST(XorPresets, NeatPaperPresetSolvesXorOnAFewSeeds) {
  // Deterministic per seed: a regression check that the classic path evolves
  // (the 100-run comparison with the NEAT paper is robozoo-xor's).
  const XorPreset x = xor_preset("neat-paper");
  for (uint64_t seed = 1; seed <= 3; ++seed) {
    Rng rng(seed);
    Population pop(x.params, Regime::FeedForward, x.layout, rng);
    bool solved = false;
    for (int gen = 0; gen < 300 && !solved; ++gen) {
      std::vector<double> f;
      for (const auto& g : pop.genomes()) {
        const XorResult r = evaluate_xor(g, x.layout, x.rules);
        f.push_back(r.fitness);
        solved |= r.solved;
        ASSERT_FALSE(has_cycle(g));
      }
      if (!solved) pop.advance(f, rng);
    }
    EXPECT_TRUE(solved) << "seed " << seed;
  }
}

TEST(XorPresets, NeatPaperPresetSwitchesOnStanleysMechanicsTheDefaultPresetDoesNot) {
  const XorPreset x = xor_preset("neat-paper");
  const NeatParams& p = x.params;
  EXPECT_EQ(p.weight_mutation, WeightMutationRule::Stanley);
  EXPECT_EQ(p.weight_perturbation, 2.5);
  EXPECT_EQ(p.weight_limit, 8.0);
  EXPECT_EQ(p.initial_weight_range, 1.0);
  EXPECT_EQ(p.mate_average_probability, 0.4);
  EXPECT_EQ(p.mate_only_probability, 0.2);
  EXPECT_EQ(p.crossover_rule, CrossoverRule::Stanley);
  EXPECT_TRUE(p.independent_parents);
  EXPECT_FALSE(p.keep_generation_champion);
  EXPECT_EQ(p.species_elitism_min_offspring, 6);
  EXPECT_EQ(p.stagnation, StagnationRule::Stanley);
  EXPECT_EQ(p.dropoff_factor, 0.01);
  EXPECT_EQ(p.offspring_rounding, OffspringRounding::Skim);
  EXPECT_EQ(p.population_stagnation_generations, 20);
  EXPECT_FALSE(p.split_bias_links);
  EXPECT_TRUE(p.structural_draw_decides);
  EXPECT_TRUE(p.childless_species_stay);
  EXPECT_TRUE(x.rules.stanley_activation);
  EXPECT_TRUE(x.rules.half_is_one);
  EXPECT_TRUE(x.count_to_solver);
  validate_neat_params(p);
  const XorPreset d = xor_preset("default");
  EXPECT_EQ(config_to_json(RunConfig{}).dump(), [&] {
    RunConfig c;
    c.neat = d.params;
    c.neat.hidden_activations = NeatParams{}.hidden_activations;
    return config_to_json(c).dump();
  }()) << "the default preset is the project's NEAT";
  EXPECT_FALSE(d.rules.stanley_activation);
  EXPECT_FALSE(d.rules.half_is_one);
  EXPECT_FALSE(d.count_to_solver);
}

}  // namespace
}  // namespace robozoo
