// The mechanics of HyperNEAT's own NEAT (NEAT_GeneticIndividual, NEAT_GeneticSpecies,
// NEAT_GeneticPopulation; the first author's later copy in jauerb/CPPN_Trimesh) that robozoo reproduces as
// options and uses by default. Every expectation is worked out by hand from HyperNEAT's rule,
// not read back from the code; where the rule draws random numbers, a second generator with the
// same seed replays the draws the rule makes, in the rule's order.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "evolve/config/run_config.hpp"
#include "evolve/neat/variation/crossover.hpp"
#include "evolve/neat/variation/mutation.hpp"
#include "evolve/neat/population.hpp"
#include "evolve/neat/species/reproduction.hpp"
#include "evolve/neat/species/speciation.hpp"
#include "evolve/neat/xor/xor_presets.hpp"
#include "evolve/neat/xor/xor_task.hpp"
#include "tests/evolve/neat/tiny_genome.hpp"

namespace robozoo {
namespace {

Genome base(int64_t id) { return test::tiny_genome(id, Activation::SignedSigmoid); }

// a: 0->3 (0), 1->3 (1), 0->4 (3), 4->3 (4); hidden 4 at 0.5.
Genome parent_a() {
  Genome g = base(1);
  g.nodes.push_back({4, NodeKind::Hidden, Activation::Gaussian, 0.5});
  g.links = {{0, 0, 3, 1.0, true, 0}, {1, 1, 3, 2.0, true, 0}, {3, 0, 4, 1.5, true, 1}, {4, 4, 3, -0.5, true, 1}};
  return g;
}
// b: 0->3 (0), 1->3 (1), 2->3 (2); hidden 5 at 0.5 with 2->5 (5), 5->3 (6).
Genome parent_b() {
  Genome g = base(2);
  g.nodes.push_back({5, NodeKind::Hidden, Activation::SignedCosine, 0.5});
  g.links = {{0, 0, 3, -1.0, true, 0},
             {1, 1, 3, -3.0, true, 0},
             {2, 2, 3, 4.0, true, 0},
             {5, 2, 5, 1.0, true, 2},
             {6, 5, 3, 2.0, true, 2}};
  return g;
}

NeatParams genes(CrossoverGenes c) {
  NeatParams p;
  p.crossover_genes = c;
  return p;
}

std::vector<int64_t> innovations(const Genome& g) {
  std::vector<int64_t> v;
  for (const auto& l : g.links) v.push_back(l.innovation);
  return v;
}
std::vector<int32_t> node_ids(const Genome& g) {
  std::vector<int32_t> v;
  for (const auto& n : g.nodes) v.push_back(n.id);
  return v;
}

// ---------------------------------------------------------------- crossover

TEST(HyperNeatCrossover, BothKeepsEveryGeneAndPicksMatchingGenesByFitnessShare) {
  // Fitness 3 and 1: a matching gene comes from a with probability 3/4, one draw per matching
  // gene (innovations 0 and 1), none for the others.
  for (uint64_t seed = 1; seed <= 20; ++seed) {
    Rng rng(seed), replay(seed);
    const Genome c = crossover(parent_a(), 3.0, parent_b(), 1.0, genes(CrossoverGenes::Both), false, rng);
    EXPECT_EQ(innovations(c), (std::vector<int64_t>{0, 1, 2, 3, 4, 5, 6}));
    EXPECT_EQ(node_ids(c), (std::vector<int32_t>{0, 1, 2, 3, 4, 5}));
    const bool first_from_a = replay.bernoulli(0.75);
    const bool second_from_a = replay.bernoulli(0.75);
    EXPECT_EQ(c.links[0].weight, first_from_a ? 1.0 : -1.0);
    EXPECT_EQ(c.links[1].weight, second_from_a ? 2.0 : -3.0);
    EXPECT_EQ(c.links[2].weight, 4.0);
    EXPECT_EQ(c.links[6].weight, 2.0);
    EXPECT_EQ(rng.state(), replay.state()) << "two draws in all";
    EXPECT_EQ(c.id, -1);
  }
  Rng rng(99);
  int from_a = 0;
  const int n = 20000;
  for (int k = 0; k < n; ++k)
    from_a +=
        crossover(parent_a(), 3.0, parent_b(), 1.0, genes(CrossoverGenes::Both), false, rng).links[0].weight == 1.0;
  EXPECT_NEAR(from_a / double(n), 0.75, 0.01);
}

TEST(HyperNeatCrossover, DrawnMakesOneDrawPerGeneAndKeepsTheDrawnParentsGenes) {
  // Union of innovations 0..6; draw k decides position k: a matching gene from the drawn parent,
  // a's own genes (3, 4) kept when a is drawn, b's own genes (2, 5, 6) when b is drawn. The hidden
  // nodes are those the kept links touch.
  int differed = 0;
  for (uint64_t seed = 1; seed <= 40; ++seed) {
    Rng rng(seed), replay(seed);
    const Genome c = crossover(parent_a(), 3.0, parent_b(), 1.0, genes(CrossoverGenes::Drawn), false, rng);
    std::vector<bool> a_drawn;
    for (int k = 0; k < 7; ++k) a_drawn.push_back(replay.bernoulli(0.75));
    EXPECT_EQ(rng.state(), replay.state()) << "seven draws in all";
    std::vector<int64_t> want;
    std::vector<double> weights;
    const double wa[] = {1.0, 2.0}, wb[] = {-1.0, -3.0};
    for (int k = 0; k < 2; ++k) {
      want.push_back(k);
      weights.push_back(a_drawn[static_cast<size_t>(k)] ? wa[k] : wb[k]);
    }
    if (!a_drawn[2]) want.push_back(2), weights.push_back(4.0);
    if (a_drawn[3]) want.push_back(3), weights.push_back(1.5);
    if (a_drawn[4]) want.push_back(4), weights.push_back(-0.5);
    if (!a_drawn[5]) want.push_back(5), weights.push_back(1.0);
    if (!a_drawn[6]) want.push_back(6), weights.push_back(2.0);
    ASSERT_EQ(innovations(c), want) << "seed " << seed;
    for (size_t i = 0; i < weights.size(); ++i) EXPECT_EQ(c.links[i].weight, weights[i]);
    std::vector<int32_t> nodes{0, 1, 2, 3};
    if (a_drawn[3] || a_drawn[4]) nodes.push_back(4);
    if (!a_drawn[5] || !a_drawn[6]) nodes.push_back(5);
    EXPECT_EQ(node_ids(c), nodes);
    differed += c.links.size() != 4 && c.links.size() != 5;
  }
  EXPECT_GT(differed, 0) << "the child's structure need not be either parent's";
  // Kept with the drawn parent's share: b's own gene 2 with 1/4, a's own gene 3 with 3/4.
  Rng rng(7);
  int kept2 = 0, kept3 = 0;
  const int n = 20000;
  for (int k = 0; k < n; ++k) {
    const Genome c = crossover(parent_a(), 3.0, parent_b(), 1.0, genes(CrossoverGenes::Drawn), false, rng);
    for (const auto& l : c.links) {
      kept2 += l.innovation == 2;
      kept3 += l.innovation == 3;
    }
  }
  EXPECT_NEAR(kept2 / double(n), 0.25, 0.01);
  EXPECT_NEAR(kept3 / double(n), 0.75, 0.01);
}

TEST(HyperNeatCrossover, AParentOfFitnessZeroCountsAsOneTenThousandth) {
  // a: fitness 0 -> 0.0001, b: 1 -> a drawn with probability 0.0001 / 1.0001.
  for (uint64_t seed = 1; seed <= 10; ++seed) {
    Rng rng(seed), replay(seed);
    const Genome c = crossover(parent_a(), 0.0, parent_b(), 1.0, genes(CrossoverGenes::Both), false, rng);
    EXPECT_EQ(c.links[0].weight, replay.bernoulli(0.0001 / 1.0001) ? 1.0 : -1.0);
  }
  // Both 0: even odds.
  Rng rng(5);
  int from_a = 0;
  const int n = 20000;
  for (int k = 0; k < n; ++k)
    from_a +=
        crossover(parent_a(), 0.0, parent_b(), 0.0, genes(CrossoverGenes::Both), false, rng).links[0].weight == 1.0;
  EXPECT_NEAR(from_a / double(n), 0.5, 0.01);
}

TEST(HyperNeatCrossover, FitterIsRobozoosRule) {
  Rng rng(3);
  const Genome c = crossover(parent_a(), 3.0, parent_b(), 1.0, genes(CrossoverGenes::Fitter), false, rng);
  EXPECT_EQ(innovations(c), (std::vector<int64_t>{0, 1, 3, 4}));
  EXPECT_EQ(node_ids(c), (std::vector<int32_t>{0, 1, 2, 3, 4}));
}

TEST(HyperNeatCrossover, UnionWithTheCycleTestIsRefusedInTheFeedForwardRegime) {
  NeatParams p;
  p.link_rule = LinkRule::CycleTest;
  EXPECT_THROW(validate_regime_params(Regime::FeedForward, p), std::invalid_argument);
  EXPECT_NO_THROW(validate_regime_params(Regime::Recurrent, p));
  p.crossover_genes = CrossoverGenes::Fitter;
  EXPECT_NO_THROW(validate_regime_params(Regime::FeedForward, p));
}

// ---------------------------------------------------------------- mutation

// 0->3, 1->3, 2->3 born in generation 0.
Genome three_links() {
  Genome g = base(7);
  g.links = {{0, 0, 3, 1.0, true, 0}, {1, 1, 3, -1.0, true, 0}, {2, 2, 3, 2.0, true, 0}};
  return g;
}

TEST(HyperNeatMutation, IndependentDrawsGiveNodeLinkAndWeightsTogether) {
  // All three probabilities 1. Add-node splits one of the three links (new node 4 at 0.5, links
  // x->4 and 4->3); add-link then has exactly the two other inputs' links into node 4 to choose
  // from (3 -> 4 goes backwards, 4 -> 4 is a self-loop); the weights are then perturbed, every
  // link being younger than 18 generations: no unsplit start link keeps its weight.
  const GenomeLayout layout = xor_layout();
  NeatParams p;
  p.add_node_probability = p.add_link_probability = p.mutate_weights_probability = 1.0;
  for (uint64_t seed = 1; seed <= 10; ++seed) {
    Genome g = three_links();
    InnovationTracker t(first_free_innovation(layout), layout.first_hidden());
    Rng rng(seed);
    mutate(g, Regime::FeedForward, layout, p, t, 1, rng);
    ASSERT_EQ(g.nodes.size(), 5u);
    ASSERT_EQ(g.links.size(), 6u);
    int from_inputs_to_4 = 0, unchanged = 0;
    for (const auto& l : g.links) {
      from_inputs_to_4 += l.to == 4 && l.from <= 2;
      if (l.innovation <= 2) unchanged += l.weight == three_links().links[static_cast<size_t>(l.innovation)].weight;
    }
    EXPECT_EQ(from_inputs_to_4, 2);
    EXPECT_EQ(unchanged, 0);
  }
  // robozoo's order: the node only.
  p.mutation_order = MutationOrder::OneStructural;
  Genome g = three_links();
  InnovationTracker t(first_free_innovation(layout), layout.first_hidden());
  Rng rng(1);
  mutate(g, Regime::FeedForward, layout, p, t, 1, rng);
  EXPECT_EQ(g.nodes.size(), 5u);
  EXPECT_EQ(g.links.size(), 5u);
  int unchanged = 0;
  for (const auto& l : g.links)
    if (l.innovation <= 2) unchanged += l.weight == three_links().links[static_cast<size_t>(l.innovation)].weight;
  EXPECT_EQ(unchanged, 2) << "the two unsplit links keep their weights";
}

TEST(HyperNeatMutation, AFailedStructuralMutationStillLetsTheWeightsMutate) {
  // Add-node off, and every allowed pair already linked (each input to the only output): add-link
  // fails, and the weights still mutate (HyperNEAT's draws are independent).
  const GenomeLayout layout = xor_layout();
  NeatParams p;
  p.add_node_probability = 0.0;
  p.add_link_probability = 1.0;
  p.mutate_weights_probability = 1.0;
  Genome g = three_links();  // every input already reaches the only output
  InnovationTracker t(first_free_innovation(layout), layout.first_hidden());
  Rng rng(4);
  mutate(g, Regime::FeedForward, layout, p, t, 1, rng);
  ASSERT_EQ(g.links.size(), 3u);
  for (size_t i = 0; i < 3; ++i) EXPECT_NE(g.links[i].weight, three_links().links[i].weight);
}

// ---------------------------------------------------------------- offspring

TEST(HyperNeatOffspring, FloorsThenOneEachToTheBestGenomesSpecies) {
  // 3/4.5*10 = 6.67 -> 6, 1/4.5*10 = 2.22 -> 2, 0.5/4.5*10 = 1.11 -> 1: one left, to the species of
  // the best genome (species 1).
  EXPECT_EQ(allocate_offspring_best_first({3.0, 1.0, 0.5}, 10, {1, 0, 2, 0}), (std::vector<int>{6, 3, 1}));
  // 2 + 2 + 2 of 8: the two best genomes' species get one each (both species 2).
  EXPECT_EQ(allocate_offspring_best_first({1.0, 1.0, 1.0}, 8, {2, 2, 0}), (std::vector<int>{2, 2, 4}));
  // Nothing shared: the walk goes round the ranking (0, 1, 0, 1, 0).
  EXPECT_EQ(allocate_offspring_best_first({0.0, 0.0}, 5, {0, 1}), (std::vector<int>{3, 2}));
  // Largest remainder would give {7, 2, 1}: the leftover follows the ranking, not the fractions.
  EXPECT_EQ(allocate_offspring({3.0, 1.0, 0.5}, 10, {1, 1, 1}), (std::vector<int>{7, 2, 1}));
  EXPECT_THROW(allocate_offspring_best_first({-1.0, 1.0}, 4, {0}), std::invalid_argument);
  EXPECT_THROW(allocate_offspring_best_first({1.0, 1.0, 1.0}, 8, {}), std::invalid_argument);
  EXPECT_THROW(allocate_offspring_best_first({1.0, 1.0, 1.0}, 8, {3}), std::invalid_argument);
}

// ---------------------------------------------------------------- threshold

TEST(HyperNeatThreshold, HalvedOrDoubledNearTheFloorElseMoved) {
  NeatParams p;  // modifier 0.3, floor 0.3, target 8
  EXPECT_DOUBLE_EQ(adjust_threshold(6.0, 5, p), 5.7);
  EXPECT_DOUBLE_EQ(adjust_threshold(6.0, 10, p), 6.3);
  EXPECT_EQ(adjust_threshold(6.0, 8, p), 6.0);
  EXPECT_EQ(adjust_threshold(0.5, 5, p), 0.25);        // 0.5 < 0.3 + 0.3: halved
  EXPECT_EQ(adjust_threshold(0.0005, 5, p), 0.0005);   // raised to 0.001, halved
  EXPECT_EQ(adjust_threshold(0.4, 10, p), 0.8);        // 0.4 < 0.3 + 0.3: doubled
  EXPECT_EQ(adjust_threshold(0.2, 8, p), 0.4);         // 0.2 < 0 + 0.3: doubled
  EXPECT_DOUBLE_EQ(adjust_threshold(0.7, 5, p), 0.4);  // 0.7 >= 0.6: moved
  p.threshold_rule = ThresholdRule::Clamp;
  EXPECT_EQ(adjust_threshold(0.5, 5, p), 0.3);
  EXPECT_EQ(adjust_threshold(0.2, 8, p), 0.2);
}

// ---------------------------------------------------------------- species

// A fixed fitness of the genome's weights, so that species persist and improve now and then.
double weight_fitness(const Genome& g) {
  double s = 0;
  for (const auto& l : g.links) s += std::fabs(l.weight);
  return 1.0 + std::fmod(s * 7.31, 5.0);
}

size_t species_champion(const Species& s, const std::vector<double>& f) {
  size_t c = static_cast<size_t>(s.members.front());
  for (int m : s.members)
    if (f[static_cast<size_t>(m)] > f[c]) c = static_cast<size_t>(m);
  return c;
}

TEST(HyperNeatSpecies, StagnationLagsTheImprovementByOneGeneration) {
  // HyperNEAT: a species founded in g0 is stagnant from g0 + dropoff_age; an improvement of its
  // best fitness (not in its first generation) or holding the generation champion in h lifts the
  // penalty until h + dropoff_age, judged before generation h's own improvement.
  NeatParams p;
  p.population = 60;
  p.dropoff_age = 4;
  p.compatibility_threshold = 1.0;
  p.target_species = 6;
  Rng rng(8);
  Population pop(p, Regime::FeedForward, xor_layout(), rng);
  std::map<int32_t, int32_t> founded, lifted;  // species id -> founding; -> last lift (h)
  std::map<int32_t, double> best;              // species id -> best raw fitness ever
  int stagnant = 0, not_stagnant = 0;
  for (int gen = 0; gen < 40; ++gen) {
    std::vector<double> f;
    for (const auto& g : pop.genomes()) f.push_back(weight_fitness(g));
    const size_t champ = static_cast<size_t>(std::max_element(f.begin(), f.end()) - f.begin());
    const std::vector<Species> species = pop.species();
    for (const auto& s : species)
      if (!founded.count(s.id)) founded[s.id] = gen;
    pop.advance(f, rng);
    const GenerationReport& rep = pop.last_report();
    ASSERT_EQ(rep.species_ids.size(), species.size());
    for (size_t k = 0; k < species.size(); ++k) {
      const Species& s = species[k];
      const int32_t since = lifted.count(s.id) ? lifted[s.id] : founded[s.id] - 1;
      const bool expected = gen - since >= p.dropoff_age + 1;
      ASSERT_EQ(rep.stagnant[k], expected) << "generation " << gen << " species " << s.id;
      (expected ? stagnant : not_stagnant)++;
      const double b = f[species_champion(s, f)];
      const bool first = founded[s.id] == gen;
      if (!first && b > best[s.id]) lifted[s.id] = gen;
      if (first || b > best[s.id]) best[s.id] = b;
      if (std::find(s.members.begin(), s.members.end(), static_cast<int>(champ)) != s.members.end())
        lifted[s.id] = gen;  // HyperNEAT's exemption for the generation champion's species
    }
  }
  EXPECT_GT(stagnant, 5);
  EXPECT_GT(not_stagnant, 40);
}

TEST(HyperNeatSpecies, TheRepresentativeIsTheBestGenomeTheSpeciesEverHad) {
  NeatParams p;
  p.population = 60;
  p.compatibility_threshold = 1.0;
  p.target_species = 6;
  Rng rng(9);
  Population pop(p, Regime::FeedForward, xor_layout(), rng);
  std::map<int32_t, std::pair<double, Genome>> best;  // species id -> best ever (first champion first)
  int replaced_later = 0, kept_old = 0;
  for (int gen = 0; gen < 30; ++gen) {
    std::vector<double> f;
    for (const auto& g : pop.genomes()) f.push_back(weight_fitness(g));
    for (const auto& s : pop.species()) {
      const size_t c = species_champion(s, f);
      auto it = best.find(s.id);
      if (it == best.end()) {
        best[s.id] = {f[c], pop.genomes()[c]};
      } else if (f[c] > it->second.first) {
        it->second = {f[c], pop.genomes()[c]};
        ++replaced_later;
      } else {
        ++kept_old;
      }
    }
    pop.advance(f, rng);
    for (const auto& s : pop.species()) {
      auto it = best.find(s.id);
      if (it == best.end()) continue;  // founded in this speciation: represented by its founder
      EXPECT_EQ(s.representative, it->second.second) << "generation " << gen << " species " << s.id;
    }
  }
  EXPECT_GT(replaced_later, 0);
  EXPECT_GT(kept_old, 0);
}

TEST(HyperNeatSpecies, AChildlessSpeciesStaysACandidate) {
  NeatParams d;
  EXPECT_TRUE(d.childless_species_stay);
  EXPECT_EQ(d.interspecies_mating_probability, 0.0) << "HyperNEAT has no interspecies mating";
}

// ---------------------------------------------------------------- the named sets, configuration

TEST(HyperNeatMechanics, DefaultsAreHyperNeatsAndRobozoosStayByName) {
  const NeatParams d;
  EXPECT_EQ(neat_mechanics_of(d), "hyperneat");
  EXPECT_EQ(d.crossover_genes, CrossoverGenes::Drawn);
  EXPECT_EQ(d.mutation_order, MutationOrder::Independent);
  EXPECT_EQ(d.representative, Representative::BestEver);
  EXPECT_EQ(d.threshold_rule, ThresholdRule::HyperNeat);
  EXPECT_EQ(d.stagnation, StagnationRule::HyperNeat);
  EXPECT_EQ(d.offspring_rounding, OffspringRounding::BestFirst);
  NeatParams r;
  apply_neat_mechanics(r, NeatMechanics::Robozoo);
  EXPECT_EQ(neat_mechanics_of(r), "robozoo");
  EXPECT_EQ(r.crossover_genes, CrossoverGenes::Fitter);
  EXPECT_EQ(r.mutation_order, MutationOrder::OneStructural);
  EXPECT_EQ(r.representative, Representative::Champion);
  EXPECT_EQ(r.threshold_rule, ThresholdRule::Clamp);
  EXPECT_EQ(r.stagnation, StagnationRule::Robozoo);
  EXPECT_EQ(r.offspring_rounding, OffspringRounding::LargestRemainder);
  EXPECT_FALSE(r.childless_species_stay);
  EXPECT_EQ(r.interspecies_mating_probability, 0.001);
  r.crossover_genes = CrossoverGenes::Both;
  EXPECT_EQ(neat_mechanics_of(r), "custom");
  // The XOR check of the NEAT paper keeps robozoo's mechanics.
  const NeatParams x = xor_preset("neat-paper").params;
  EXPECT_EQ(x.crossover_genes, CrossoverGenes::Fitter);
  EXPECT_EQ(x.mutation_order, MutationOrder::OneStructural);
  EXPECT_EQ(x.representative, Representative::Champion);
  EXPECT_EQ(x.threshold_rule, ThresholdRule::Clamp);
}

TEST(HyperNeatMechanics, ConfigKeysRoundTripAndTheSetIsReadFirst) {
  const nlohmann::json d = config_to_json(RunConfig{});
  EXPECT_EQ(d["neat"]["mechanics"], "hyperneat");
  EXPECT_EQ(d["neat"]["crossover_genes"], "drawn");
  EXPECT_EQ(d["neat"]["mutation_order"], "independent");
  EXPECT_EQ(d["neat"]["representative"], "best_ever");
  EXPECT_EQ(d["neat"]["threshold_rule"], "hyperneat");
  EXPECT_EQ(d["neat"]["stagnation"], "hyperneat");
  EXPECT_EQ(d["neat"]["offspring_rounding"], "best_first");
  // The set alone.
  RunConfig c = config_from_json({{"neat", {{"mechanics", "robozoo"}}}});
  EXPECT_EQ(neat_mechanics_of(c.neat), "robozoo");
  // A key beside it overrides it, whatever the keys' order ("crossover_genes" sorts before
  // "mechanics", "threshold_rule" after).
  c = config_from_json(
      {{"neat", {{"mechanics", "robozoo"}, {"crossover_genes", "both"}, {"threshold_rule", "hyperneat"}}}});
  EXPECT_EQ(c.neat.crossover_genes, CrossoverGenes::Both);
  EXPECT_EQ(c.neat.threshold_rule, ThresholdRule::HyperNeat);
  EXPECT_EQ(c.neat.mutation_order, MutationOrder::OneStructural);
  const nlohmann::json j = config_to_json(c);
  EXPECT_EQ(j["neat"]["mechanics"], "custom");
  const RunConfig back = config_from_json(j);
  EXPECT_EQ(config_to_json(back), j);
  EXPECT_EQ(back.neat.crossover_genes, CrossoverGenes::Both);
  // TOML too.
  const RunConfig t = config_from_text("[neat]\nmechanics = \"robozoo\"\nrepresentative = \"best_ever\"\n",
                                       ConfigFormat::Toml, "t.toml");
  EXPECT_EQ(t.neat.representative, Representative::BestEver);
  EXPECT_EQ(t.neat.stagnation, StagnationRule::Robozoo);
  EXPECT_THROW(config_from_json({{"neat", {{"mechanics", "stanley"}}}}), ConfigError);
  EXPECT_THROW(config_from_json({{"neat", {{"crossover_genes", "all"}}}}), ConfigError);
  EXPECT_THROW(config_from_json({{"neat", {{"mutation_order", 1}}}}), ConfigError);
  EXPECT_THROW(config_from_json({{"neat", {{"offspring_rounding", "best"}}}}), ConfigError);
}

TEST(HyperNeatMechanics, ARunIsReproducible) {
  NeatParams p;
  p.population = 50;
  for (Regime regime : {Regime::FeedForward, Regime::Recurrent}) {
    Rng r1(21), r2(21);
    Population a(p, regime, xor_layout(), r1), b(p, regime, xor_layout(), r2);
    for (int gen = 0; gen < 15; ++gen) {
      std::vector<double> f;
      for (const auto& g : a.genomes()) f.push_back(weight_fitness(g));
      a.advance(f, r1);
      b.advance(f, r2);
      for (const auto& g : a.genomes()) validate_genome(g, xor_layout());
      for (const auto& g : a.genomes()) validate_regime_links(g, regime, p);
    }
    EXPECT_EQ(a.state(), b.state());
  }
}

}  // namespace
}  // namespace robozoo
