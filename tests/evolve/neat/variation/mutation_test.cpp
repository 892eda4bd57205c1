#include "evolve/neat/variation/mutation.hpp"

#include <gtest/gtest.h>

#include <map>
#include <set>
#include <tuple>

#include "evolve/neat/start/initial_genome.hpp"
#include "tests/evolve/neat/classic_params.hpp"
#include "tests/evolve/neat/tiny_genome.hpp"

namespace robozoo {
namespace {

// The genome with every link gene enabled: acyclic iff the graph of all genes is.
Genome all_enabled(Genome g) {
  for (auto& l : g.links) l.enabled = true;
  return g;
}

bool has_self_loop(const Genome& g) {
  for (const auto& l : g.links)
    if (l.from == l.to) return true;
  return false;
}

// Grows a genome by many random structural mutations, new tracker generation each round.
void grow(Genome& g, Regime regime, const GenomeLayout& layout, const NeatParams& p, InnovationTracker& t, int rounds,
          Rng& rng, int* added_links = nullptr) {
  for (int r = 0; r < rounds; ++r) {
    t.new_generation();
    if (rng.bernoulli(0.2)) mutate_add_node(g, p, t, r, rng);
    const bool added = mutate_add_link(g, regime, layout, p, t, r, rng);
    if (added_links) *added_links += added;
    validate_genome(g, layout);
  }
}

TEST(MutateAddLink, FeedForwardNeverClosesACycle) {
  const GenomeLayout layout = test::tiny_layout(2);
  NeatParams p = classic_neat();
  Rng rng(1);
  int total_added = 0;
  for (int trial = 0; trial < 40; ++trial) {
    Genome g = initial_genome(layout, trial, p, Regime::FeedForward, rng);
    InnovationTracker t(first_free_innovation(layout), layout.first_hidden());
    int added = 0;
    for (int r = 0; r < 100; ++r) {
      t.new_generation();
      if (rng.bernoulli(0.2)) mutate_add_node(g, p, t, r, rng);
      added += mutate_add_link(g, Regime::FeedForward, layout, p, t, r, rng);
      ASSERT_FALSE(has_cycle(g)) << "trial " << trial << " round " << r;
      ASSERT_FALSE(has_cycle(all_enabled(g))) << "a disabled gene could close a cycle later";
      for (const auto& l : g.links) ASSERT_GE(l.to, layout.num_inputs) << "link into an input";
    }
    validate_genome(g, layout);
    total_added += added;
  }
  EXPECT_GT(total_added, 1000) << "add-link should usually find a legal link";
}

TEST(MutateAddLink, RecurrentRegimeMakesCyclesAndSelfLoops) {
  const GenomeLayout layout = test::tiny_layout(2);
  NeatParams p = classic_neat();
  Rng rng(2);
  int cyclic = 0, self_loops = 0;
  for (int trial = 0; trial < 30; ++trial) {
    Genome g = initial_genome(layout, trial, p, Regime::FeedForward, rng);
    InnovationTracker t(first_free_innovation(layout), layout.first_hidden());
    grow(g, Regime::Recurrent, layout, p, t, 30, rng);
    for (const auto& l : g.links) ASSERT_GE(l.to, layout.num_inputs) << "link into an input";
    cyclic += has_cycle(g);
    self_loops += has_self_loop(g);
  }
  EXPECT_GT(cyclic, 15);
  EXPECT_GT(self_loops, 5);
}

TEST(MutateAddLink, NewLinkIsNewBornAndRegistered) {
  const GenomeLayout layout = test::tiny_layout(2);
  NeatParams p = classic_neat();
  Rng rng(3);
  Genome g = initial_genome(layout, 0, p, Regime::FeedForward, rng);
  InnovationTracker t(first_free_innovation(layout), layout.first_hidden());
  // Fully connected, no hidden node: in the recurrent regime only output -> output links are new.
  ASSERT_TRUE(mutate_add_link(g, Regime::Recurrent, layout, p, t, 7, rng));
  ASSERT_EQ(g.links.size(), 7u);
  const LinkGene& l = g.links.back();
  EXPECT_EQ(l.innovation, first_free_innovation(layout));
  EXPECT_EQ(l.born, 7);
  EXPECT_TRUE(l.enabled);
  EXPECT_GE(l.from, layout.num_inputs);
  EXPECT_LE(std::abs(l.weight), p.initial_weight_range);
  // A second genome making the same link this generation gets the same innovation.
  Genome h = initial_genome(layout, 1, p, Regime::FeedForward, rng);
  for (int k = 0; k < 100 && h.links.size() == 6; ++k) {
    Genome tmp = h;
    if (mutate_add_link(tmp, Regime::Recurrent, layout, p, t, 7, rng) && tmp.links.back().from == l.from &&
        tmp.links.back().to == l.to)
      h = tmp;
  }
  ASSERT_EQ(h.links.size(), 7u);
  EXPECT_EQ(h.links.back().innovation, l.innovation);
}

TEST(MutateAddLink, FailsWhenNoLegalLinkExists) {
  const GenomeLayout layout = test::tiny_layout(2);
  NeatParams p = classic_neat();
  Rng rng(4);
  Genome g = initial_genome(layout, 0, p, Regime::FeedForward, rng);
  InnovationTracker t(first_free_innovation(layout), layout.first_hidden());
  // Feed-forward, fully connected inputs -> outputs: only output -> output links
  // remain, 3 -> 4 or 4 -> 3; add one, and the other would close a cycle.
  int added = 0;
  for (int k = 0; k < 50; ++k) added += mutate_add_link(g, Regime::FeedForward, layout, p, t, 0, rng);
  EXPECT_EQ(added, 1);
  EXPECT_FALSE(has_cycle(g));
}

TEST(MutateAddNode, SplitsAnEnabledLink) {
  const GenomeLayout layout = test::tiny_layout(2);
  NeatParams p = classic_neat();
  p.hidden_activations = 1u << static_cast<int>(Activation::Gaussian);
  Rng rng(5);
  Genome g = initial_genome(layout, 0, p, Regime::FeedForward, rng);
  const Genome before = g;
  InnovationTracker t(first_free_innovation(layout), layout.first_hidden());
  ASSERT_TRUE(mutate_add_node(g, p, t, 4, rng));
  validate_genome(g, layout);
  ASSERT_EQ(count_hidden(g), 1);
  const NodeGene& h = g.nodes.back();
  EXPECT_EQ(h.id, layout.first_hidden());
  EXPECT_EQ(h.activation, Activation::Gaussian);
  ASSERT_EQ(g.links.size(), before.links.size() + 2);
  // Exactly one old link was disabled; in-link weight 1, out-link the old weight.
  const LinkGene* split = nullptr;
  for (size_t i = 0; i < before.links.size(); ++i)
    if (!g.links[i].enabled) {
      ASSERT_EQ(split, nullptr);
      split = &g.links[i];
      EXPECT_EQ(g.links[i].weight, before.links[i].weight);
    }
  ASSERT_NE(split, nullptr);
  const LinkGene& in = g.links[before.links.size()];
  const LinkGene& out = g.links[before.links.size() + 1];
  EXPECT_EQ(in.from, split->from);
  EXPECT_EQ(in.to, h.id);
  EXPECT_EQ(in.weight, 1.0);
  EXPECT_EQ(out.from, h.id);
  EXPECT_EQ(out.to, split->to);
  EXPECT_EQ(out.weight, split->weight);
  EXPECT_EQ(in.born, 4);
  EXPECT_EQ(out.born, 4);
  EXPECT_TRUE(in.enabled && out.enabled);
}

TEST(MutateAddNode, SameSplitInOneGenerationSharesNodeAndInnovations) {
  const GenomeLayout layout = test::tiny_layout(2);
  NeatParams p = classic_neat();
  Rng rng(6);
  InnovationTracker t(first_free_innovation(layout), layout.first_hidden());
  // Many genomes split their links in one generation: the same split link must
  // always give the same node gene and link innovations.
  std::map<int64_t, std::tuple<int32_t, int64_t, int64_t, Activation>> seen;
  int repeats = 0;
  for (int i = 0; i < 60; ++i) {
    Genome g = initial_genome(layout, i, p, Regime::FeedForward, rng);
    ASSERT_TRUE(mutate_add_node(g, p, t, 1, rng));
    int64_t split = -1;
    for (const auto& l : g.links)
      if (!l.enabled) split = l.innovation;
    const NodeGene& h = g.nodes.back();
    const auto key = std::make_tuple(h.id, g.links[6].innovation, g.links[7].innovation, h.activation);
    const auto it = seen.find(split);
    if (it == seen.end()) {
      seen.emplace(split, key);
    } else {
      ++repeats;
      EXPECT_EQ(it->second, key);
    }
  }
  EXPECT_GT(repeats, 30);
  EXPECT_EQ(seen.size(), 6u);
  // A new generation: the same split gets a new node id.
  t.new_generation();
  Genome g = initial_genome(layout, 99, p, Regime::FeedForward, rng);
  ASSERT_TRUE(mutate_add_node(g, p, t, 2, rng));
  EXPECT_EQ(g.nodes.back().id, layout.first_hidden() + 6);
}

TEST(MutateAddNode, ActivationsComeFromTheMask) {
  const GenomeLayout layout = test::tiny_layout(2);
  NeatParams p = classic_neat();  // signed sigmoid, signed cosine, Gaussian
  Rng rng(7);
  std::set<Activation> got;
  for (int i = 0; i < 200; ++i) {
    InnovationTracker t(first_free_innovation(layout), layout.first_hidden());
    Genome g = initial_genome(layout, i, p, Regime::FeedForward, rng);
    ASSERT_TRUE(mutate_add_node(g, p, t, 1, rng));
    got.insert(g.nodes.back().activation);
  }
  EXPECT_EQ(got, (std::set<Activation>{Activation::SignedSigmoid, Activation::SignedCosine, Activation::Gaussian}));
  p.hidden_activations = 0;
  InnovationTracker t(first_free_innovation(layout), layout.first_hidden());
  Genome g = initial_genome(layout, 0, p, Regime::FeedForward, rng);
  EXPECT_THROW(mutate_add_node(g, p, t, 1, rng), std::invalid_argument);
}

TEST(MutateAddNode, FailsWithoutEnabledLinks) {
  const GenomeLayout layout = test::tiny_layout(2);
  NeatParams p = classic_neat();
  Rng rng(8);
  Genome g = initial_genome(layout, 0, p, Regime::FeedForward, rng);
  for (auto& l : g.links) l.enabled = false;
  InnovationTracker t(first_free_innovation(layout), layout.first_hidden());
  EXPECT_FALSE(mutate_add_node(g, p, t, 1, rng));
  EXPECT_EQ(count_hidden(g), 0);
}

TEST(MutateWeights, YoungLinksAlwaysOldOnesSometimes) {
  const GenomeLayout layout = test::tiny_layout(2);
  NeatParams p = classic_neat();
  Rng rng(9);
  // Young: generation - born < 18, always perturbed.
  int young_changed = 0, young_total = 0, old_changed = 0, old_total = 0;
  for (int i = 0; i < 500; ++i) {
    Genome g = initial_genome(layout, i, p, Regime::FeedForward, rng);
    const Genome before = g;
    mutate_weights(g, p, /*generation=*/17, rng);
    for (size_t k = 0; k < g.links.size(); ++k) {
      ++young_total;
      young_changed += g.links[k].weight != before.links[k].weight;
      ASSERT_LE(std::abs(g.links[k].weight - before.links[k].weight), p.weight_perturbation);
    }
    Genome o = before;
    mutate_weights(o, p, /*generation=*/18, rng);
    for (size_t k = 0; k < o.links.size(); ++k) {
      ++old_total;
      old_changed += o.links[k].weight != before.links[k].weight;
    }
  }
  EXPECT_EQ(young_changed, young_total);
  // Binomial(3000, 0.1): mean 300, sd ~16.
  EXPECT_GT(old_changed, 230);
  EXPECT_LT(old_changed, 370);
}

TEST(MutateWeights, ClampsToTheLimit) {
  const GenomeLayout layout = test::tiny_layout(2);
  NeatParams p = classic_neat();
  Rng rng(10);
  Genome g = initial_genome(layout, 0, p, Regime::FeedForward, rng);
  bool hit = false;
  for (int r = 0; r < 200; ++r) {
    mutate_weights(g, p, 0, rng);
    for (const auto& l : g.links) {
      ASSERT_LE(std::abs(l.weight), p.weight_limit);
      hit |= std::abs(l.weight) == p.weight_limit;
    }
  }
  EXPECT_TRUE(hit) << "a random walk of +-2.5 steps reaches the +-5 bounds";
}

TEST(Mutate, AtMostOneStructuralChangeAndWeightsOnlyWithoutOne) {
  const GenomeLayout layout = test::tiny_layout(2);
  NeatParams p = classic_neat();
  p.add_node_probability = 0.5;
  p.add_link_probability = 0.5;
  p.mutate_weights_probability = 1.0;
  Rng rng(11);
  int nodes = 0, links = 0, weights = 0;
  for (int i = 0; i < 300; ++i) {
    InnovationTracker t(first_free_innovation(layout), layout.first_hidden());
    Genome g = initial_genome(layout, i, p, Regime::FeedForward, rng);
    const Genome before = g;
    mutate(g, Regime::Recurrent, layout, p, t, 1, rng);
    const size_t added = g.links.size() - before.links.size();
    ASSERT_TRUE(added == 0 || added == 1 || added == 2);
    bool weights_changed = false;
    for (size_t k = 0; k < before.links.size(); ++k) weights_changed |= g.links[k].weight != before.links[k].weight;
    if (added == 2) {
      ++nodes;
      EXPECT_FALSE(weights_changed);
    }
    if (added == 1) {
      ++links;
      EXPECT_FALSE(weights_changed);
    }
    if (added == 0) {
      ++weights;
      EXPECT_TRUE(weights_changed);
    }
  }
  EXPECT_GT(nodes, 100);
  EXPECT_GT(links, 40);
  EXPECT_GT(weights, 40);
}

// A small hand-made genome for HyperNEAT's rules: inputs 0, 1, 2 (2 is the
// bias) at position 0, outputs 3, 4 at position 1, hidden node 5 at 0.5 (the
// split of 0 -> 3), links 0 -> 5 and 5 -> 3.
Genome hand_genome() {
  Genome g;
  g.id = 7;
  g.nodes = {
      {0, NodeKind::Input, Activation::Linear, 0.0},         {1, NodeKind::Input, Activation::Linear, 0.0},
      {2, NodeKind::Bias, Activation::Linear, 0.0},          {3, NodeKind::Output, Activation::SignedSigmoid, 1.0},
      {4, NodeKind::Output, Activation::SignedSigmoid, 1.0}, {5, NodeKind::Hidden, Activation::Gaussian, 0.5}};
  g.links = {{100, 0, 5, 1.0, true, 0}, {101, 5, 3, 2.0, true, 0}};
  return g;
}

// Chi-square statistic of observed counts against equal expected counts.
double chi_square(const std::map<std::pair<int, int>, int>& counts, int draws) {
  const double expected = static_cast<double>(draws) / counts.size();
  double x2 = 0.0;
  for (const auto& [pair, n] : counts) x2 += (n - expected) * (n - expected) / expected;
  return x2;
}

std::map<std::pair<int, int>, int> add_link_choices(Regime regime, int draws, uint64_t seed) {
  const GenomeLayout layout = test::tiny_layout(2);
  const NeatParams p;  // HyperNEAT: uniform add-link, positions, no self-loops
  Rng rng(seed);
  std::map<std::pair<int, int>, int> counts;
  for (int k = 0; k < draws; ++k) {
    Genome g = hand_genome();
    InnovationTracker t(1000, 6);
    EXPECT_TRUE(mutate_add_link(g, regime, layout, p, t, 3, rng));
    const LinkGene& l = g.links.back();  // innovation 1000 sorts last
    ++counts[{l.from, l.to}];
  }
  return counts;
}

TEST(MutateAddLinkUniform, FeedForwardChoosesUniformlyAmongTheFreeForwardPairs) {
  // Forward pairs (pos(from) < pos(to)), by hand: from each input (0) to 3, 4, 5
  // (9) and from 5 (0.5) to 3, 4 (2): 11; 0 -> 5 and 5 -> 3 exist: 9 are free.
  const std::set<std::pair<int, int>> expected = {{0, 3}, {0, 4}, {1, 3}, {1, 4}, {1, 5},
                                                  {2, 3}, {2, 4}, {2, 5}, {5, 4}};
  const int draws = 9000;
  const auto counts = add_link_choices(Regime::FeedForward, draws, 21);
  std::set<std::pair<int, int>> got;
  for (const auto& [pair, n] : counts) got.insert(pair);
  EXPECT_EQ(got, expected);
  // 8 degrees of freedom: P(chi2 > 26.12) = 0.001.
  EXPECT_LT(chi_square(counts, draws), 26.12);
}

TEST(MutateAddLinkUniform, RecurrentChoosesUniformlyAmongAllFreePairsButSelfLoops) {
  // Any of the 6 nodes to any of the 3 non-inputs: 18, minus 3 self-loops, minus
  // the 2 existing links: 13 free pairs, backward ones (3 -> 5, 4 -> 5, 3 -> 4, ...) included.
  const int draws = 13000;
  const auto counts = add_link_choices(Regime::Recurrent, draws, 22);
  ASSERT_EQ(counts.size(), 13u);
  for (const auto& [pair, n] : counts) {
    EXPECT_NE(pair.first, pair.second);
    EXPECT_GE(pair.second, 3);
    EXPECT_FALSE(pair == std::make_pair(0, 5) || pair == std::make_pair(5, 3));
  }
  EXPECT_EQ(counts.count({3, 5}), 1u);
  EXPECT_EQ(counts.count({4, 3}), 1u);
  // 12 degrees of freedom: P(chi2 > 32.91) = 0.001.
  EXPECT_LT(chi_square(counts, draws), 32.91);
}

TEST(MutateAddLinkUniform, FailsOnlyWhenNoPairIsLeft) {
  const GenomeLayout layout = robot_layout();
  const NeatParams p;
  Rng rng(23);
  // The feed-forward start already links every forward pair; so does the
  // recurrent one, less self-loops.
  for (Regime regime : {Regime::FeedForward, Regime::Recurrent}) {
    Genome g = initial_genome(layout, 0, p, regime, rng);
    InnovationTracker t(first_free_innovation(layout), layout.first_hidden());
    EXPECT_FALSE(mutate_add_link(g, regime, layout, p, t, 1, rng));
    // One split opens new pairs: the hidden node at 0.5 may take links.
    ASSERT_TRUE(mutate_add_node(g, p, t, 1, rng));
    EXPECT_TRUE(mutate_add_link(g, regime, layout, p, t, 1, rng));
  }
}

TEST(MutateAddNodeHyperNeat, KeepsTheLinkAtHalfWeightAndAddsOneAndAQuarter) {
  const GenomeLayout layout = test::tiny_layout(2);
  NeatParams p;
  ASSERT_EQ(p.add_node, AddNodeRule::HyperNeat);
  Rng rng(24);
  // Only 5 -> 3 (0.5 -> 1, w = 2) is forward and enabled once 0 -> 5 is disabled.
  Genome g = hand_genome();
  g.links[0].enabled = false;
  InnovationTracker t(1000, 6);
  ASSERT_TRUE(mutate_add_node(g, p, t, 9, rng));
  validate_genome(g, layout);
  ASSERT_EQ(g.nodes.size(), 7u);
  const NodeGene& h = g.nodes.back();
  EXPECT_EQ(h.id, 6);
  EXPECT_EQ(h.position, 0.75);  // (0.5 + 1) / 2
  ASSERT_EQ(g.links.size(), 4u);
  EXPECT_TRUE(g.links[1].enabled);
  EXPECT_EQ(g.links[1].weight, 1.0);  // 2 / 2
  EXPECT_EQ(g.links[1].born, 9);      // the split link is young again
  const LinkGene& in = g.links[2];
  const LinkGene& out = g.links[3];
  EXPECT_EQ(std::make_tuple(in.from, in.to, in.weight, in.born), std::make_tuple(5, 6, 1.0, 9));
  EXPECT_EQ(std::make_tuple(out.from, out.to, out.weight, out.born), std::make_tuple(6, 3, 0.5, 9));  // 2 / 4
  EXPECT_TRUE(in.enabled && out.enabled);
}

TEST(MutateAddNodeHyperNeat, EverySplitGetsNewNumbersEvenOfTheSameLink) {
  // HyperNEAT's numbering (the default): many genomes of one generation split links of
  // the same start; no two splits share a node id or a link innovation, whichever link
  // they split. The same draws with shared numbers repeat node ids.
  const GenomeLayout layout = test::tiny_layout(2);
  for (AddNodeInnovations numbers : {AddNodeInnovations::Fresh, AddNodeInnovations::Shared}) {
    NeatParams p;
    ASSERT_EQ(NeatParams{}.add_node_innovations, AddNodeInnovations::Fresh);
    p.add_node_innovations = numbers;
    Rng rng(6);
    InnovationTracker t(first_free_innovation(layout), layout.first_hidden());
    std::set<int32_t> nodes;
    std::set<int64_t> innovations;
    const int genomes = 60;
    for (int i = 0; i < genomes; ++i) {
      Genome g = initial_genome(layout, i, p, Regime::FeedForward, rng);
      ASSERT_TRUE(mutate_add_node(g, p, t, 1, rng));
      validate_genome(g, layout);
      nodes.insert(g.nodes.back().id);
      for (const auto& l : g.links)
        if (l.from == g.nodes.back().id || l.to == g.nodes.back().id) innovations.insert(l.innovation);
    }
    if (numbers == AddNodeInnovations::Fresh) {
      EXPECT_EQ(nodes.size(), static_cast<size_t>(genomes));
      EXPECT_EQ(innovations.size(), static_cast<size_t>(2 * genomes));
      EXPECT_EQ(t.next_node_id(), layout.first_hidden() + genomes);
    } else {
      EXPECT_LT(nodes.size(), 10u) << "the same split, the same node";
    }
  }
}

TEST(MutateAddNodeHyperNeat, SplitsForwardLinksOnly) {
  const GenomeLayout layout = test::tiny_layout(2);
  const NeatParams p;
  Rng rng(25);
  // Only recurrent links: 3 -> 4 (1 -> 1), 4 -> 3, 3 -> 5 (1 -> 0.5), and a disabled forward one.
  Genome g = hand_genome();
  g.links = {
      {100, 0, 5, 1.0, false, 0}, {110, 3, 4, 1.0, true, 0}, {111, 4, 3, 1.0, true, 0}, {112, 3, 5, 1.0, true, 0}};
  InnovationTracker t(1000, 6);
  EXPECT_FALSE(mutate_add_node(g, p, t, 1, rng));
  // The classic rule splits them (and disables the split link).
  NeatParams classic = p;
  classic.add_node = AddNodeRule::Classic;
  ASSERT_TRUE(mutate_add_node(g, classic, t, 1, rng));
  int disabled = 0;
  for (const auto& l : g.links) disabled += !l.enabled;
  EXPECT_EQ(disabled, 2);
  validate_genome(g, layout);
}

// Rounds of add-node and add-link, each with probability 1/2, and weight mutations.
Genome mutated_start(Regime regime, const NeatParams& p, int64_t id, int rounds, Rng& rng) {
  const GenomeLayout layout = robot_layout();
  Genome g = initial_genome(layout, id, p, regime, rng);
  InnovationTracker t(first_free_innovation(layout), layout.first_hidden());
  for (int r = 0; r < rounds; ++r) {
    t.new_generation();
    if (rng.bernoulli(0.5)) mutate_add_node(g, p, t, r, rng);
    if (rng.bernoulli(0.5)) mutate_add_link(g, regime, layout, p, t, r, rng);
    mutate_weights(g, p, r, rng);
  }
  validate_genome(g, layout);
  return g;
}

TEST(HyperNeatRules, ControlRegimeHoldsForwardLinksOnlyAfterManyMutations) {
  const NeatParams p;
  Rng rng(26);
  int hidden = 0, links = 0;
  for (int trial = 0; trial < 20; ++trial) {
    const Genome g = mutated_start(Regime::FeedForward, p, trial, 60, rng);
    for (const auto& l : g.links) {
      ASSERT_TRUE(is_forward_link(g, l)) << l.from << " -> " << l.to;
      ASSERT_NE(l.from, l.to);
    }
    ASSERT_FALSE(has_cycle(all_enabled(g)));
    hidden += count_hidden(g);
    links += static_cast<int>(g.links.size());
  }
  EXPECT_GT(hidden, 20 * 10) << "the test must have grown real structure";
  EXPECT_GT(links, 20 * 99 + 20 * 30);
}

TEST(HyperNeatRules, RecurrentRegimeNeverMakesSelfLoopsAndKeepsItsCycles) {
  const NeatParams p;
  Rng rng(27);
  for (int trial = 0; trial < 10; ++trial) {
    const Genome g = mutated_start(Regime::Recurrent, p, trial, 60, rng);
    EXPECT_FALSE(has_self_loop(g));
    EXPECT_TRUE(has_cycle(g));
    EXPECT_GE(count_recurrent_links(g), 110);
    // Every hidden node sits strictly between the ends of some forward path: (0, 1).
    for (const auto& n : g.nodes)
      if (n.kind == NodeKind::Hidden) {
        EXPECT_GT(n.position, 0.0);
        EXPECT_LT(n.position, 1.0);
      }
  }
}

}  // namespace
}  // namespace robozoo
