#include "evolve/neat/start/initial_genome.hpp"

#include <gtest/gtest.h>

#include "tests/evolve/neat/classic_params.hpp"

#include <set>
#include <vector>

#include "evolve/cppn/network.hpp"

namespace robozoo {
namespace {

TEST(InitialGenome, LinksEveryInputToEveryOutputWithSharedInnovations) {
  const GenomeLayout layout = robot_layout();
  NeatParams p = classic_neat();
  Rng rng(3);
  const Genome a = initial_genome(layout, 0, p, Regime::FeedForward, rng);
  const Genome b = initial_genome(layout, 1, p, Regime::FeedForward, rng);
  validate_genome(a, layout);
  EXPECT_EQ(a.id, 0);
  EXPECT_EQ(b.id, 1);
  EXPECT_EQ(count_hidden(a), 0);
  ASSERT_EQ(a.links.size(), static_cast<size_t>(layout.num_inputs * layout.num_outputs));
  EXPECT_EQ(a.nodes.size(), static_cast<size_t>(layout.num_inputs + layout.num_outputs));
  EXPECT_EQ(a.nodes[4].kind, NodeKind::Bias);
  EXPECT_EQ(a.nodes[9].kind, NodeKind::Output);
  std::set<std::pair<int, int>> pairs;
  bool weights_differ = false;
  for (size_t k = 0; k < a.links.size(); ++k) {
    const LinkGene& l = a.links[k];
    EXPECT_EQ(l.innovation, initial_link_innovation(layout, l.from, l.to - layout.num_inputs));
    EXPECT_EQ(l.innovation, b.links[k].innovation);
    EXPECT_EQ(l.from, b.links[k].from);
    EXPECT_EQ(l.to, b.links[k].to);
    EXPECT_TRUE(l.enabled);
    EXPECT_EQ(l.born, 0);
    EXPECT_GE(l.weight, -p.initial_weight_range);
    EXPECT_LE(l.weight, p.initial_weight_range);
    weights_differ |= l.weight != b.links[k].weight;
    pairs.insert({l.from, l.to});
  }
  EXPECT_EQ(pairs.size(), a.links.size());
  EXPECT_TRUE(weights_differ);
  // (9 inputs + 11 outputs) x 11 outputs innovations are reserved for start links.
  EXPECT_EQ(first_free_innovation(layout), 220);
}

// HyperNEAT's createTopology with edge density 1: every node to every non-input
// node that the regime allows. Counted by hand for the robot layout (9 inputs,
// 11 outputs): feed-forward 9 x 11 = 99 input -> output links (output -> output
// links join two nodes at position 1: not forward); recurrent 99 + 11 x 10 = 209
// (self-loops are not allowed), 220 with self-loops.
TEST(InitialGenome, HyperNeatStartLinksEverythingTheRegimeAllows) {
  const GenomeLayout layout = robot_layout();
  NeatParams p;
  ASSERT_EQ(p.initial_links, InitialLinks::AllAllowed);
  ASSERT_FALSE(p.self_loops);
  Rng rng(5);
  const Genome ff = initial_genome(layout, 0, p, Regime::FeedForward, rng);
  const Genome rec = initial_genome(layout, 1, p, Regime::Recurrent, rng);
  validate_genome(ff, layout);
  validate_genome(rec, layout);
  EXPECT_EQ(ff.links.size(), 99u);
  EXPECT_EQ(rec.links.size(), 209u);
  EXPECT_EQ(count_recurrent_links(ff), 0);
  EXPECT_EQ(count_recurrent_links(rec), 110);
  EXPECT_FALSE(has_cycle(ff));
  EXPECT_TRUE(has_cycle(rec));
  int output_to_output = 0;
  std::set<std::pair<int, int>> pairs;
  for (const auto& l : rec.links) {
    EXPECT_NE(l.from, l.to) << "no self-loop";
    EXPECT_GE(l.to, layout.num_inputs) << "no link into an input";
    output_to_output += l.from >= layout.num_inputs;
    pairs.insert({l.from, l.to});
    EXPECT_EQ(l.innovation, initial_link_innovation(layout, l.from, l.to - layout.num_inputs));
    EXPECT_LT(l.innovation, first_free_innovation(layout));
  }
  EXPECT_EQ(output_to_output, 110);
  EXPECT_EQ(pairs.size(), 209u);
  for (const auto& n : rec.nodes) EXPECT_EQ(n.position, n.kind == NodeKind::Output ? 1.0 : 0.0) << "node " << n.id;
  // Both regimes give an input -> output link the same innovation number.
  for (size_t k = 0; k < ff.links.size(); ++k) {
    EXPECT_EQ(ff.links[k].from, rec.links[k].from);
    EXPECT_EQ(ff.links[k].innovation, rec.links[k].innovation);
  }
  p.self_loops = true;
  EXPECT_EQ(initial_genome(layout, 2, p, Regime::Recurrent, rng).links.size(), 220u);
  EXPECT_EQ(initial_genome(layout, 3, p, Regime::FeedForward, rng).links.size(), 99u);
  // The third arm's start: recurrence allowed, the control's 99 links.
  p.initial_links = InitialLinks::InputsToOutputs;
  EXPECT_EQ(initial_genome(layout, 4, p, Regime::Recurrent, rng).links.size(), 99u);
}

// The fourth arm's start: the recurrent start's 209 links and weight draws, the
// 110 output -> output links at exactly 0.
TEST(InitialGenome, RecurrentZeroStartIsTheRecurrentStartWithSilentRecurrentLinks) {
  const GenomeLayout layout = robot_layout();
  NeatParams full, zero, sparse;
  zero.initial_links = InitialLinks::AllAllowedRecurrentZero;
  sparse.initial_links = InitialLinks::InputsToOutputs;
  EXPECT_EQ(initial_links_name(zero.initial_links), "all_allowed_recurrent_zero");
  EXPECT_EQ(initial_links_from_name("all_allowed_recurrent_zero"), InitialLinks::AllAllowedRecurrentZero);
  Rng rng_full(42), rng_zero(42);
  for (int id = 0; id < 20; ++id) {
    const Genome f = initial_genome(layout, id, full, Regime::Recurrent, rng_full);
    const Genome z = initial_genome(layout, id, zero, Regime::Recurrent, rng_zero);
    validate_genome(z, layout);
    ASSERT_EQ(z.links.size(), 209u);
    ASSERT_EQ(f.links.size(), 209u);
    EXPECT_EQ(count_recurrent_links(z), 110);
    EXPECT_TRUE(has_cycle(z));
    int zeros = 0, drawn = 0;
    for (size_t k = 0; k < z.links.size(); ++k) {
      const LinkGene &a = f.links[k], &b = z.links[k];
      EXPECT_EQ(a.innovation, b.innovation);
      EXPECT_EQ(a.from, b.from);
      EXPECT_EQ(a.to, b.to);
      EXPECT_TRUE(b.enabled);
      EXPECT_EQ(b.born, 0);
      if (b.from >= layout.num_inputs) {
        EXPECT_EQ(b.weight, 0.0) << "link " << b.from << " -> " << b.to;
        EXPECT_NE(a.weight, 0.0);
        ++zeros;
      } else {
        EXPECT_EQ(b.weight, a.weight) << "the same draw as the recurrent start's";
        ++drawn;
      }
    }
    EXPECT_EQ(zeros, 110);
    EXPECT_EQ(drawn, 99);
  }
  // Both streams made the same draws: the next number agrees.
  EXPECT_EQ(rng_full.uniform(0, 1), rng_zero.uniform(0, 1));

  // Behaviour: the same outputs, bit for bit, as the genome without its 110
  // silent links (the 99-link start with these weights), although the network is
  // recurrent and takes its synchronous updates.
  Rng rng(7);
  const Genome z = initial_genome(layout, 0, zero, Regime::Recurrent, rng);
  Genome s = z;
  s.links.resize(99);
  for (const auto& l : s.links) ASSERT_LT(l.from, layout.num_inputs);
  Network nz(z, layout), ns(s, layout);
  Rng in_rng(9);
  for (int q = 0; q < 200; ++q) {
    std::vector<double> in(static_cast<size_t>(layout.num_inputs));
    for (auto& v : in) v = in_rng.uniform(-2, 2);
    in[static_cast<size_t>(layout.bias_input)] = 1.0;
    const std::vector<double> a = nz.query(in), b = ns.query(in);
    ASSERT_EQ(a.size(), b.size());
    for (size_t o = 0; o < a.size(); ++o) ASSERT_EQ(a[o], b[o]) << "query " << q << ", output " << o;
  }
  // Self-loops, when allowed, come from an output too: 220 links, 121 at 0.
  zero.self_loops = true;
  const Genome zs = initial_genome(layout, 1, zero, Regime::Recurrent, rng);
  EXPECT_EQ(zs.links.size(), 220u);
  int zs_zeros = 0;
  for (const auto& l : zs.links) zs_zeros += l.weight == 0.0;
  EXPECT_EQ(zs_zeros, 121);
  // In the feed-forward regime no link leaves an output: it is the 99-link start.
  Rng a(3), b(3);
  zero.self_loops = false;
  const Genome zf = initial_genome(layout, 0, zero, Regime::FeedForward, a);
  const Genome ff = initial_genome(layout, 0, full, Regime::FeedForward, b);
  ASSERT_EQ(zf.links.size(), 99u);
  for (size_t k = 0; k < zf.links.size(); ++k) EXPECT_EQ(zf.links[k].weight, ff.links[k].weight);
}

TEST(InitialGenome, WeightsCoverTheirRange) {
  GenomeLayout layout;
  layout.num_inputs = 3;
  layout.bias_input = 2;
  layout.num_outputs = 1;
  NeatParams p = classic_neat();
  Rng rng(11);
  double lo = 0, hi = 0;
  for (int i = 0; i < 300; ++i)
    for (const auto& l : initial_genome(layout, i, p, Regime::FeedForward, rng).links) {
      lo = std::min(lo, l.weight);
      hi = std::max(hi, l.weight);
    }
  EXPECT_LT(lo, -2.8);
  EXPECT_GT(hi, 2.8);
}

TEST(InitialGenome, RejectsEmptyLayouts) {
  GenomeLayout layout;
  layout.num_outputs = 0;
  NeatParams p = classic_neat();
  Rng rng(1);
  EXPECT_THROW(initial_genome(layout, 0, p, Regime::FeedForward, rng), std::invalid_argument);
}

}  // namespace
}  // namespace robozoo
