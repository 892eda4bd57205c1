// The mechanics of Stanley's own NEAT C++ that robozoo reproduces as options
// (evolve/neat/params.hpp; the neat-paper XOR preset switches them on). Every
// expectation below is worked out by hand from the rule, not read back from the code.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "evolve/config/run_config.hpp"
#include "evolve/neat/species/compatibility.hpp"
#include "evolve/neat/variation/crossover.hpp"
#include "evolve/neat/variation/mutation.hpp"
#include "evolve/neat/population.hpp"
#include "evolve/neat/population_json.hpp"
#include "evolve/neat/species/reproduction.hpp"
#include "evolve/neat/xor/xor_task.hpp"
#include "tests/evolve/neat/classic_params.hpp"
#include "tests/evolve/neat/tiny_genome.hpp"

namespace robozoo {
namespace {

GenomeLayout small_layout() { return xor_layout(Activation::SteepenedSigmoid); }

Genome base(int64_t id) { return test::tiny_genome(id, Activation::SteepenedSigmoid); }

// a: 0->3 (0), 1->3 (1, disabled), 2->3 (2), 0->4 (3), 4->3 (4, disabled); hidden 4.
Genome parent_a() {
  Genome g = base(1);
  g.nodes.push_back({4, NodeKind::Hidden, Activation::SteepenedSigmoid, 0.5});
  g.links = {{0, 0, 3, 1.0, true, 0},
             {1, 1, 3, 2.0, false, 0},
             {2, 2, 3, 3.0, true, 0},
             {3, 0, 4, 1.5, true, 1},
             {4, 4, 3, -0.5, false, 1}};
  return g;
}
// b: 0->3 (0), 1->3 (1), 2->3 (2); no hidden node.
Genome parent_b() {
  Genome g = base(2);
  g.links = {{0, 0, 3, -1.0, true, 0}, {1, 1, 3, -3.0, true, 0}, {2, 2, 3, 4.0, true, 0}};
  return g;
}

NeatParams stanley_crossover() {
  NeatParams p = classic_neat();
  p.crossover_rule = CrossoverRule::Stanley;
  p.disabled_gene_probability = 0.75;
  return p;
}

// ---------------------------------------------------------------- crossover

TEST(StanleyCrossover, AveragingGivesTheMeanOfTheParentsWeights) {
  const NeatParams p = stanley_crossover();
  Rng rng(1);
  for (int k = 0; k < 20; ++k) {
    const Genome c = crossover(parent_a(), 2.0, parent_b(), 1.0, p, /*average_weights=*/true, rng);
    ASSERT_EQ(c.links.size(), 5u);       // a is fitter: its structure
    EXPECT_EQ(c.links[0].weight, 0.0);   // (1 + -1) / 2
    EXPECT_EQ(c.links[1].weight, -0.5);  // (2 + -3) / 2
    EXPECT_EQ(c.links[2].weight, 3.5);   // (3 + 4) / 2
    EXPECT_EQ(c.links[3].weight, 1.5);   // disjoint: a's own
    EXPECT_EQ(c.links[4].weight, -0.5);  // excess: a's own
    EXPECT_TRUE(c.links[0].enabled);
    EXPECT_TRUE(c.links[2].enabled);
    EXPECT_FALSE(c.links[4].enabled) << "an unmatched gene keeps its flag under Stanley's rule";
  }
}

TEST(StanleyCrossover, EnabledFlagsFollowStanleysMateFunctions) {
  // Gene 1 is disabled in a, enabled in b. Copying (mate_multipoint): disabled with 0.75, else
  // the chosen gene's flag (a's, disabled, half the time): 0.75 + 0.25 * 0.5 = 0.875.
  // Averaging (mate_multipoint_avg): disabled with 0.75, else enabled: 0.75.
  // Gene 4 (excess, disabled in a) is never re-enabled; the robozoo rule re-enables it 25 %.
  const NeatParams p = stanley_crossover();
  NeatParams robozoo = p;
  robozoo.crossover_rule = CrossoverRule::Robozoo;
  Rng rng(2);
  const int n = 40000;
  int copy_disabled = 0, avg_disabled = 0, excess_enabled = 0, robozoo_excess_enabled = 0;
  for (int k = 0; k < n; ++k) {
    const Genome c = crossover(parent_a(), 2.0, parent_b(), 1.0, p, false, rng);
    copy_disabled += !c.links[1].enabled;
    excess_enabled += c.links[4].enabled;
    const Genome v = crossover(parent_a(), 2.0, parent_b(), 1.0, p, true, rng);
    avg_disabled += !v.links[1].enabled;
    excess_enabled += v.links[4].enabled;
    robozoo_excess_enabled += crossover(parent_a(), 2.0, parent_b(), 1.0, robozoo, false, rng).links[4].enabled;
  }
  EXPECT_NEAR(copy_disabled / double(n), 0.875, 0.01);
  EXPECT_NEAR(avg_disabled / double(n), 0.75, 0.01);
  EXPECT_EQ(excess_enabled, 0);
  EXPECT_NEAR(robozoo_excess_enabled / double(n), 0.25, 0.01);
}

TEST(StanleyCrossover, OnEqualFitnessTheSmallerGenomeIsTheFitter) {
  const NeatParams p = stanley_crossover();
  Rng rng(3);
  // Equal fitness: b (3 genes) is smaller than a (5): the child has b's structure whichever
  // parent comes first; the robozoo rule takes the first.
  EXPECT_EQ(crossover(parent_a(), 1.0, parent_b(), 1.0, p, false, rng).links.size(), 3u);
  EXPECT_EQ(crossover(parent_b(), 1.0, parent_a(), 1.0, p, false, rng).links.size(), 3u);
  NeatParams robozoo = p;
  robozoo.crossover_rule = CrossoverRule::Robozoo;
  EXPECT_EQ(crossover(parent_a(), 1.0, parent_b(), 1.0, robozoo, false, rng).links.size(), 5u);
  // Equal sizes: the second parent's structure (Stanley: p1 is better only when smaller).
  Genome a2 = parent_b();
  a2.id = 7;
  a2.nodes.push_back({5, NodeKind::Hidden, Activation::SteepenedSigmoid, 0.5});
  a2.links.push_back({7, 0, 5, 1.0, true, 1});
  Genome b2 = parent_b();
  b2.nodes.push_back({6, NodeKind::Hidden, Activation::SteepenedSigmoid, 0.5});
  b2.links.push_back({8, 1, 6, 1.0, true, 1});
  EXPECT_EQ(crossover(a2, 1.0, b2, 1.0, p, false, rng).links.back().innovation, 8);
  EXPECT_EQ(crossover(b2, 1.0, a2, 1.0, p, false, rng).links.back().innovation, 7);
}

// ---------------------------------------------------------------- weight mutation

TEST(StanleyWeightMutation, SevereHalfOfTheCallsAndAStrongerTail) {
  // Weights start at 100 with the clamp at 1000: a perturbation (|d| < 2.5) leaves them within
  // 2.5 of 100, a replacement puts them within 2.5 of 0, a kept one stays exactly 100.
  // 20 genes: the tail is index > 16 (17, 18, 19).
  // Head gene: severe (1/2) 70/20/10, else always perturbed -> kept 0.05, replaced 0.10.
  // Tail gene: severe 70/20/10, else 50/20/30 -> kept 0.20, replaced 0.20.
  NeatParams p;
  p.weight_mutation = WeightMutationRule::Stanley;
  p.weight_perturbation = 2.5;
  p.weight_limit = 1000.0;
  Genome g0 = base(0);
  for (int i = 0; i < 20; ++i) g0.links.push_back({i, 0, 3, 100.0, true, 0});
  Rng rng(4);
  const int calls = 20000;
  int head_kept = 0, head_replaced = 0, tail_kept = 0, tail_replaced = 0, all_perturbed_calls = 0;
  for (int k = 0; k < calls; ++k) {
    Genome g = g0;
    mutate_weights(g, p, 0, rng);
    bool all_head_perturbed = true;
    for (int i = 0; i < 20; ++i) {
      const double w = g.links[static_cast<size_t>(i)].weight;
      const bool kept = w == 100.0, replaced = std::fabs(w) <= 2.5;
      ASSERT_TRUE(kept || replaced || std::fabs(w - 100.0) <= 2.5) << w;
      if (i <= 16) {
        head_kept += kept;
        head_replaced += replaced;
        all_head_perturbed = all_head_perturbed && !kept && !replaced;
      } else {
        tail_kept += kept;
        tail_replaced += replaced;
      }
    }
    all_perturbed_calls += all_head_perturbed;
  }
  EXPECT_NEAR(head_kept / (17.0 * calls), 0.05, 0.005);
  EXPECT_NEAR(head_replaced / (17.0 * calls), 0.10, 0.006);
  EXPECT_NEAR(tail_kept / (3.0 * calls), 0.20, 0.01);
  EXPECT_NEAR(tail_replaced / (3.0 * calls), 0.20, 0.01);
  // A non-severe call perturbs every head gene (1/2 of the calls); a severe one does so for all
  // 17 only with 0.7^17: about 0.5 + 0.5 * 0.0023.
  EXPECT_NEAR(all_perturbed_calls / double(calls), 0.5012, 0.015);
}

TEST(StanleyWeightMutation, FewerThanTenGenesHaveNoTailAndWeightsAreClamped) {
  NeatParams p;
  p.weight_mutation = WeightMutationRule::Stanley;
  p.weight_perturbation = 2.5;
  p.weight_limit = 8.0;
  Genome g0 = base(0);
  for (int i = 0; i < 9; ++i) g0.links.push_back({i, 0, 3, 7.9, true, 0});
  Rng rng(5);
  int last_kept = 0;
  const int calls = 20000;
  for (int k = 0; k < calls; ++k) {
    Genome g = g0;
    mutate_weights(g, p, 0, rng);
    for (const auto& l : g.links) ASSERT_LE(std::fabs(l.weight), 8.0);
    last_kept += g.links.back().weight == 7.9;
  }
  // 9 genes: the last one is treated like the others: kept only in severe calls, 10 %.
  EXPECT_NEAR(last_kept / double(calls), 0.05, 0.006);
}

// ---------------------------------------------------------------- structural mutation

TEST(StanleyMutation, AddNodeNeverSplitsABiasLink) {
  NeatParams p = classic_neat();
  p.split_bias_links = false;
  p.hidden_activations = 1u << static_cast<int>(Activation::SteepenedSigmoid);
  Genome g = base(0);
  g.links = {{0, 0, 3, 1.0, false, 0}, {1, 2, 3, 1.0, true, 0}};  // only the bias link is enabled
  Rng rng(6);
  InnovationTracker t(2, 4);
  EXPECT_FALSE(mutate_add_node(g, p, t, 1, rng));
  g.links[0].enabled = true;
  for (int k = 0; k < 50; ++k) {
    Genome h = g;
    InnovationTracker tk(2, 4);
    ASSERT_TRUE(mutate_add_node(h, p, tk, 1, rng));
    EXPECT_FALSE(h.links[0].enabled) << "the x1 link is the only one it may split";
    EXPECT_TRUE(h.links[1].enabled);
  }
  p.split_bias_links = true;
  int bias_splits = 0;
  for (int k = 0; k < 200; ++k) {
    Genome h = g;
    InnovationTracker tk(2, 4);
    ASSERT_TRUE(mutate_add_node(h, p, tk, 1, rng));
    bias_splits += !h.links[1].enabled;
  }
  EXPECT_GT(bias_splits, 50);
}

TEST(StanleyMutation, AFailedStructuralDrawEndsTheMutation) {
  // add_node drawn always, but nothing can be split (no enabled link): with the Stanley option
  // the offspring stays as it was; without it the weights are mutated.
  NeatParams p = classic_neat();
  p.add_node_probability = 1.0;
  p.add_link_probability = 0.0;
  p.mutate_weights_probability = 1.0;
  p.weight_mutation = WeightMutationRule::Classic;
  Genome g = base(0);
  g.links = {{0, 0, 3, 1.0, false, 0}};
  InnovationTracker t(1, 4);
  Rng rng(7);
  Genome stanley = g;
  p.structural_draw_decides = true;
  mutate(stanley, Regime::FeedForward, small_layout(), p, t, 1, rng);
  EXPECT_EQ(stanley.links, g.links);
  Genome robozoo = g;
  p.structural_draw_decides = false;
  mutate(robozoo, Regime::FeedForward, small_layout(), p, t, 1, rng);
  EXPECT_NE(robozoo.links[0].weight, 1.0);
}

// ---------------------------------------------------------------- offspring rounding

TEST(StanleySkim, FractionsAreCarriedAcrossSpecies) {
  // Mean value 1 (8 members, sum 8): every member expects its value.
  // A: 2.5 -> 2, carry .5; .75 -> carry 1.25 > 1 -> +1, carry .25            A = 3
  // B: .5 -> carry .75; .25 -> carry 1.0, not above 1                         B = 0
  // C: 1.5 -> 1, carry 1.5 -> +1, .5; 1.25 -> 1, .75; .75 -> 1.5 -> +1, .5; .5 -> 1.0    C = 4
  // Shortfall 8 - 7 = 1 -> the species with the most (C, 4) gets it.
  const std::vector<std::vector<double>> v = {{2.5, 0.75}, {0.5, 0.25}, {1.5, 1.25, 0.75, 0.5}};
  EXPECT_EQ(allocate_offspring_skim(v, 8), (std::vector<int>{3, 0, 5}));
  // Largest remainder on the species' sums (3.25, 0.75, 4.0) would give (3, 1, 4).
  EXPECT_EQ(allocate_offspring({3.25, 0.75, 4.0}, 8, {2, 2, 4}), (std::vector<int>{3, 1, 4}));
  // Ties for the most: the last of them gets the shortfall. A: 1.5 -> 1, .5; .5 -> 1.0 (no);
  // B: 1 -> 1; 1 -> 1: (1, 2), short by one -> B (2 >= 1).
  EXPECT_EQ(allocate_offspring_skim({{1.5, 0.5}, {1.0, 1.0}}, 4), (std::vector<int>{1, 3}));
  EXPECT_EQ(allocate_offspring_skim({{1.0, 1.0}, {1.0, 1.0}}, 4), (std::vector<int>{2, 2}));
  EXPECT_THROW(allocate_offspring_skim({{0.0}, {0.0}}, 4), std::invalid_argument);
  EXPECT_THROW(allocate_offspring_skim({{-1.0, 2.0}}, 4), std::invalid_argument);
}

// ---------------------------------------------------------------- population

// A population whose species persist: fitness is a fixed function of the genome's weights.
double weight_fitness(const Genome& g) {
  double s = 0;
  for (const auto& l : g.links) s += std::fabs(l.weight);
  return 1.0 + std::fmod(s * 7.31, 5.0);
}

// The NEAT paper's XOR parameters with every Stanley mechanic on (what the neat-paper preset
// sets, written out here so that these tests do not depend on the preset).
NeatParams stanley_population(int size) {
  NeatParams p = classic_neat();
  p.population = size;
  p.hidden_activations = 1u << static_cast<int>(Activation::SteepenedSigmoid);
  p.excess_coefficient = p.disjoint_coefficient = 1.0;
  p.weight_coefficient = 0.4;
  p.compatibility_threshold = 3.0;
  p.compatibility_modifier = 0.0;
  p.disabled_gene_probability = 0.75;
  p.initial_weight_range = 1.0;
  p.weight_limit = 8.0;
  p.weight_mutation = WeightMutationRule::Stanley;
  p.crossover_rule = CrossoverRule::Stanley;
  p.mate_average_probability = 0.4;
  p.mate_only_probability = 0.2;
  p.independent_parents = true;
  p.keep_generation_champion = false;
  p.species_elitism_min_offspring = 6;
  p.stagnation = StagnationRule::Stanley;
  p.dropoff_factor = 0.01;
  p.offspring_rounding = OffspringRounding::Skim;
  p.population_stagnation_generations = 20;
  p.split_bias_links = false;
  p.structural_draw_decides = true;
  p.childless_species_stay = true;
  return p;
}

TEST(StanleyPopulation, StagnationIsJudgedBeforeTheImprovementWithoutExemption) {
  NeatParams p = stanley_population(60);
  p.stagnation = StagnationRule::Stanley;
  p.dropoff_age = 4;  // stagnant from 3 generations after the last improvement
  p.population_stagnation_generations = 0;
  Rng rng(8);
  Population pop(p, Regime::FeedForward, small_layout(), rng);
  int stagnant_champion_species = 0, checked = 0;
  for (int gen = 0; gen < 40; ++gen) {
    std::vector<double> f;
    for (const auto& g : pop.genomes()) f.push_back(weight_fitness(g));
    std::map<int32_t, int32_t> last;  // species id -> last improvement before this generation
    for (const auto& s : pop.species()) last[s.id] = s.last_improvement;
    const int32_t champion_species =
        pop.species_of(static_cast<size_t>(std::max_element(f.begin(), f.end()) - f.begin()));
    pop.advance(f, rng);
    const GenerationReport& rep = pop.last_report();
    for (size_t k = 0; k < rep.species_ids.size(); ++k) {
      const bool expected = gen - last.at(rep.species_ids[k]) >= 3;
      ASSERT_EQ(rep.stagnant[k], expected) << "generation " << gen << " species " << rep.species_ids[k];
      ++checked;
      if (expected && rep.species_ids[k] == champion_species) ++stagnant_champion_species;
    }
  }
  EXPECT_GT(checked, 40);
  EXPECT_GT(stagnant_champion_species, 0) << "the champion's species is not exempt";
}

TEST(StanleyPopulation, PopulationStagnationKeepsOnlyTheTopTwoSpeciesChampions) {
  // Fitness never beats generation 0's record, so with 3 generations allowed the fourth advance
  // (generation 3) strikes: the two species with the best champions get 10 offspring each; each
  // block is 9 mutated copies of the champion (its nodes; its links, weights changed, or one
  // link more) and the champion itself last.
  NeatParams p = stanley_population(20);
  p.population_stagnation_generations = 3;
  p.compatibility_threshold = 0.4;  // several species among the random initial weights
  Rng rng(9);
  Population pop(p, Regime::FeedForward, small_layout(), rng);
  for (int gen = 0; gen < 4; ++gen) {
    std::vector<double> f;
    for (const auto& g : pop.genomes()) f.push_back(weight_fitness(g) / 10.0);
    if (gen == 0) f[0] = 1.0;  // the record: never reached again (weight_fitness / 10 < 0.6)
    const std::vector<Genome> before = pop.genomes();
    const std::vector<Species> species = pop.species();
    pop.advance(f, rng);
    const GenerationReport& rep = pop.last_report();
    if (gen < 3) {
      EXPECT_FALSE(rep.population_stagnation) << gen;
      continue;
    }
    ASSERT_TRUE(rep.population_stagnation);
    int changed = 0;
    ASSERT_GE(species.size(), 3u);
    // The champions, each species' best member (members ranked by fitness, ties in order).
    std::vector<std::pair<double, size_t>> best;  // (fitness, species index)
    std::vector<size_t> champion(species.size());
    for (size_t si = 0; si < species.size(); ++si) {
      size_t c = static_cast<size_t>(species[si].members.front());
      for (int m : species[si].members)
        if (f[static_cast<size_t>(m)] > f[c]) c = static_cast<size_t>(m);
      champion[si] = c;
      best.push_back({f[c], si});
    }
    std::stable_sort(best.begin(), best.end(), [](auto& x, auto& y) { return x.first > y.first; });
    const size_t top0 = best[0].second, top1 = best[1].second;
    for (size_t si = 0; si < species.size(); ++si)
      EXPECT_EQ(rep.offspring[si], si == top0 || si == top1 ? 10 : 0) << si;
    // Blocks in species order.
    const size_t first = std::min(top0, top1), second = std::max(top0, top1);
    for (size_t block = 0; block < 2; ++block) {
      const Genome& c = before[champion[block == 0 ? first : second]];
      for (size_t k = 0; k < 10; ++k) {
        const Genome& child = pop.genomes()[block * 10 + k];
        if (k == 9) {
          EXPECT_EQ(child.links, c.links);
          EXPECT_EQ(child.nodes, c.nodes);
          continue;
        }
        EXPECT_EQ(child.nodes, c.nodes);
        ASSERT_TRUE(child.links.size() == c.links.size() || child.links.size() == c.links.size() + 1);
        if (child.links.size() == c.links.size()) {
          for (size_t i = 0; i < c.links.size(); ++i) EXPECT_EQ(child.links[i].innovation, c.links[i].innovation);
        }
        changed += child.links != c.links;  // a failed add-link leaves a plain copy
      }
    }
    EXPECT_GE(changed, 12);
  }
}

TEST(StanleyPopulation, MatedUnmutatedOffspringAreCrossoverResults) {
  // Structure never mutates and every mutation perturbs every weight (classic, replace 0), so a
  // child whose every gene carries the weight of the same gene in some parent is a crossover of
  // two parents left unmutated. With mate_only_probability 1 all mated children are such; with
  // 0 none is (a perturbation equal to 0 has probability 0).
  for (const double mate_only : {1.0, 0.0}) {
    NeatParams p = stanley_population(40);
    p.add_node_probability = 0.0;
    p.add_link_probability = 0.0;
    p.mutate_weights_probability = 1.0;
    p.weight_mutation = WeightMutationRule::Classic;
    p.weight_replace_probability = 0.0;
    p.mutate_only_probability = 0.0;
    p.interspecies_mating_probability = 0.0;
    p.independent_parents = false;
    p.species_elitism_min_offspring = 1000;  // no champion copies
    p.compatibility_threshold = 100.0;       // one species
    p.survival_threshold = 1.0;              // every genome may be a parent
    p.population_stagnation_generations = 0;
    p.mate_only_probability = mate_only;
    p.mate_average_probability = 0.0;  // averaged weights are no parent's
    Rng rng(10);
    Population pop(p, Regime::FeedForward, small_layout(), rng);
    std::vector<double> f;
    for (const auto& g : pop.genomes()) f.push_back(weight_fitness(g));
    std::map<std::pair<int64_t, double>, int> seen;  // (innovation, weight) in the parents
    for (const auto& g : pop.genomes())
      for (const auto& l : g.links) seen[{l.innovation, l.weight}]++;
    pop.advance(f, rng);
    int crossovers = 0;
    for (const auto& child : pop.genomes()) {
      bool all_seen = true;
      for (const auto& l : child.links) all_seen = all_seen && seen.count({l.innovation, l.weight});
      crossovers += all_seen;
    }
    EXPECT_EQ(crossovers, mate_only == 1.0 ? 40 : 0) << "mate_only_probability " << mate_only;
  }
}

TEST(StanleyPopulation, IndependentParentsMayBeOneGenomeAndThenTheChildIsMutated) {
  // Two parents (survival threshold 1/40 of one species of 40), every offspring mated, mated
  // offspring unmutated (mate_only 1) unless both parents are one genome. Drawn independently,
  // the second parent is the first with probability 1/2: about 20 of the 40 offspring are
  // mutated (binomial, sd 3.2). Drawn different, none is.
  for (const bool independent : {false, true}) {
    NeatParams p = stanley_population(40);
    p.add_node_probability = p.add_link_probability = 0.0;
    p.mutate_weights_probability = 1.0;
    p.weight_mutation = WeightMutationRule::Classic;
    p.weight_replace_probability = 0.0;
    p.mutate_only_probability = 0.0;
    p.interspecies_mating_probability = 0.0;
    p.species_elitism_min_offspring = 1000;
    p.compatibility_threshold = 100.0;
    p.survival_threshold = 1.0 / 40.0;
    p.population_stagnation_generations = 0;
    p.mate_only_probability = 1.0;
    p.mate_average_probability = 0.0;
    p.independent_parents = independent;
    Rng rng(14);
    Population pop(p, Regime::FeedForward, small_layout(), rng);
    std::vector<double> f;
    for (const auto& g : pop.genomes()) f.push_back(weight_fitness(g));
    std::set<std::pair<int64_t, double>> seen;
    for (const auto& g : pop.genomes())
      for (const auto& l : g.links) seen.insert({l.innovation, l.weight});
    pop.advance(f, rng);
    int mutated = 0;
    for (const auto& child : pop.genomes()) {
      bool all_seen = true;
      for (const auto& l : child.links) all_seen = all_seen && seen.count({l.innovation, l.weight});
      mutated += !all_seen;
    }
    if (independent) {
      EXPECT_GE(mutated, 10);
      EXPECT_LE(mutated, 30);
    } else {
      EXPECT_EQ(mutated, 0);
    }
  }
}

// A hand-made state: genome i has every one of its three links at weights[i], species k holds
// the genomes with species_of[i] == k (two species), represented by its first member.
Population hand_made(const NeatParams& p, const std::vector<double>& weights, const std::vector<int>& species_of) {
  PopulationState st;
  st.next_innovation = 3;
  st.next_node_id = 4;
  st.compatibility_threshold = st.speciation_threshold = p.compatibility_threshold;
  for (size_t i = 0; i < weights.size(); ++i) {
    Genome g = base(static_cast<int64_t>(i));
    const double w = weights[i];
    g.links = {{0, 0, 3, w, true, 0}, {1, 1, 3, w, true, 0}, {2, 2, 3, w, true, 0}};
    st.genomes.push_back(g);
    st.species_of.push_back(species_of[i]);
  }
  st.next_genome_id = static_cast<int64_t>(weights.size());
  for (int k = 0; k < 2; ++k) {
    Species sp;
    sp.id = k;
    for (size_t i = 0; i < weights.size(); ++i)
      if (species_of[i] == k) sp.members.push_back(static_cast<int>(i));
    sp.representative = st.genomes[static_cast<size_t>(sp.members.front())];
    st.species.push_back(sp);
  }
  st.next_species_id = 2;
  return Population(p, Regime::FeedForward, small_layout(), st);
}

TEST(StanleyPopulation, WithoutChampionKeepingASmallSpeciesLosesItsChampion) {
  // Species 0: the champion (fitness 2) and two genomes of fitness 0.1; species 1: 17 genomes of
  // fitness 1.9. Shared values: 2/3, 0.1/3, 0.1/3 and 17 x 1.9/17; mean 2.6333/20 = 0.13167.
  // Species 0 expects 5.06 + 0.25 + 0.25: 5 offspring (the carry 0.57 is not above 1), fewer
  // than 6, so no champion copy; every offspring's weights are mutated (probability 1), so none
  // equals the champion. With keep_generation_champion the champion is copied first.
  for (const bool keep : {false, true}) {
    NeatParams p = stanley_population(20);
    p.keep_generation_champion = keep;
    p.mate_only_probability = 0.0;
    p.mutate_weights_probability = 1.0;
    p.population_stagnation_generations = 0;
    p.compatibility_threshold = 0.5;
    std::vector<double> weights(20, 2.0);
    std::vector<int> species_of(20, 1);
    for (int i = 0; i < 3; ++i) {
      weights[static_cast<size_t>(i)] = 0.0;
      species_of[static_cast<size_t>(i)] = 0;
    }
    Population pop = hand_made(p, weights, species_of);
    const Genome champion = pop.genomes()[0];
    std::vector<double> f(20, 1.9);
    f[0] = 2.0;
    f[1] = f[2] = 0.1;
    Rng rng(11);
    pop.advance(f, rng);
    if (!keep) {
      EXPECT_EQ(pop.last_report().offspring[0], 5);
    }
    int copies = 0;
    for (const auto& g : pop.genomes()) copies += g.links == champion.links;
    EXPECT_EQ(copies, keep ? 1 : 0);
    if (keep) {
      EXPECT_EQ(pop.genomes()[0].links, champion.links);
    }
  }
}

TEST(StanleyPopulation, ChildlessSpeciesCanLiveOn) {
  // Species 0: ten genomes with every weight 0, fitness 0, so it gets no offspring. Species 1:
  // ten with every weight 2, fitness 1: all 20 offspring. Distance between them 0.4 x 2 = 0.8,
  // threshold 0.5. Species 1's offspring are mutated copies and crossovers of weights near 2;
  // those whose mean weight difference to species 0's champion falls below 1.25 join species 0,
  // which comes first, when it stays a candidate: it lives on. Without the option it is gone.
  for (const bool stay : {false, true}) {
    NeatParams p = stanley_population(20);
    p.childless_species_stay = stay;
    p.compatibility_threshold = 0.5;
    std::vector<double> weights(20, 2.0);
    std::vector<int> species_of(20, 1);
    for (size_t i = 0; i < 10; ++i) {
      weights[i] = 0.0;
      species_of[i] = 0;
    }
    Population pop = hand_made(p, weights, species_of);
    std::vector<double> f(20, 0.0);
    for (size_t i = 10; i < 20; ++i) f[i] = 1.0;
    Rng rng(12);
    pop.advance(f, rng);
    EXPECT_EQ(pop.last_report().offspring, (std::vector<int>{0, 20}));
    int in_species_0 = 0;
    for (size_t i = 0; i < 20; ++i) in_species_0 += pop.species_of(i) == 0;
    if (stay) {
      EXPECT_GT(in_species_0, 0);
      EXPECT_EQ(pop.species().front().id, 0);
    } else {
      EXPECT_EQ(in_species_0, 0);
    }
  }
}

TEST(StanleyPopulation, StateWithARecordRoundTripsAndOldStatesStillRead) {
  NeatParams p = stanley_population(20);
  p.population_stagnation_generations = 20;
  Rng rng(13);
  Population pop(p, Regime::FeedForward, small_layout(), rng);
  std::vector<double> f(20, 2.0);
  pop.advance(f, rng);
  pop.advance(f, rng);
  EXPECT_EQ(pop.state().record_fitness, 2.0);
  EXPECT_EQ(pop.state().generations_since_record, 1);
  const nlohmann::json j = population_state_to_json(pop.state());
  EXPECT_EQ(population_state_from_json(j), pop.state());
  PopulationState plain = pop.state();
  plain.record_fitness = 0.0;
  plain.generations_since_record = 0;
  const nlohmann::json k = population_state_to_json(plain);
  EXPECT_FALSE(k.contains("record_fitness"));
  EXPECT_EQ(population_state_from_json(k), plain);
}

// ---------------------------------------------------------------- configuration and preset

TEST(StanleyOptions, ConfigKeysAndDefaults) {
  const NeatParams d;
  EXPECT_EQ(d.mate_average_probability, 0.0);
  EXPECT_EQ(d.mate_only_probability, 0.0);
  EXPECT_EQ(d.crossover_rule, CrossoverRule::Robozoo);
  EXPECT_FALSE(d.independent_parents);
  EXPECT_TRUE(d.keep_generation_champion);
  EXPECT_EQ(d.stagnation, StagnationRule::HyperNeat);
  EXPECT_EQ(d.offspring_rounding, OffspringRounding::BestFirst);  // HyperNEAT's, the default
  EXPECT_EQ(d.population_stagnation_generations, 0);
  EXPECT_TRUE(d.split_bias_links);
  EXPECT_FALSE(d.structural_draw_decides);
  EXPECT_TRUE(d.childless_species_stay);  // HyperNEAT keeps a species while it finds members
  const RunConfig c = config_from_json({{"neat",
                                         {{"mate_average_probability", 0.4},
                                          {"mate_only_probability", 0.2},
                                          {"crossover_rule", "stanley"},
                                          {"independent_parents", true},
                                          {"keep_generation_champion", false},
                                          {"stagnation", "stanley"},
                                          {"offspring_rounding", "skim"},
                                          {"population_stagnation_generations", 20},
                                          {"split_bias_links", false},
                                          {"structural_draw_decides", true},
                                          {"childless_species_stay", true},
                                          {"weight_mutation", "stanley"}}}});
  EXPECT_EQ(c.neat.mate_average_probability, 0.4);
  EXPECT_EQ(c.neat.mate_only_probability, 0.2);
  EXPECT_EQ(c.neat.crossover_rule, CrossoverRule::Stanley);
  EXPECT_TRUE(c.neat.independent_parents);
  EXPECT_FALSE(c.neat.keep_generation_champion);
  EXPECT_EQ(c.neat.stagnation, StagnationRule::Stanley);
  EXPECT_EQ(c.neat.offspring_rounding, OffspringRounding::Skim);
  EXPECT_EQ(c.neat.population_stagnation_generations, 20);
  EXPECT_FALSE(c.neat.split_bias_links);
  EXPECT_TRUE(c.neat.structural_draw_decides);
  EXPECT_TRUE(c.neat.childless_species_stay);
  EXPECT_EQ(c.neat.weight_mutation, WeightMutationRule::Stanley);
  EXPECT_EQ(config_from_json(config_to_json(c)).neat.offspring_rounding, OffspringRounding::Skim);
  EXPECT_THROW(config_from_json({{"neat", {{"offspring_rounding", "round"}}}}), ConfigError);
  EXPECT_THROW(config_from_json({{"neat", {{"mate_only_probability", 1.5}}}}), ConfigError);
}

}  // namespace
}  // namespace robozoo
