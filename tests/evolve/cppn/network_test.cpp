#include "evolve/cppn/network.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "evolve/core/rng.hpp"
#include "evolve/neat/random_genome.hpp"

#include <cstring>

namespace robozoo {
namespace {

// XOR-sized layout: inputs 0, 1 and bias 2; output 3; hidden from 4.
GenomeLayout small_layout() {
  GenomeLayout l;
  l.num_inputs = 3;
  l.bias_input = 2;
  l.num_outputs = 1;
  return l;
}

Genome base(const GenomeLayout& l) {
  Genome g;
  g.id = 1;
  for (int i = 0; i < l.num_inputs; ++i)
    g.nodes.push_back({i, i == l.bias_input ? NodeKind::Bias : NodeKind::Input, Activation::Linear, 0.0});
  for (int o = 0; o < l.num_outputs; ++o)
    g.nodes.push_back({l.num_inputs + o, NodeKind::Output, l.output_activation, 1.0});
  return g;
}

double ssig(double x) { return 2.0 / (1.0 + std::exp(-x)) - 1.0; }

TEST(Network, DirectLinksAreOneSignedSigmoid) {
  const auto l = small_layout();
  Genome g = base(l);
  g.links = {{0, 0, 3, 0.5, true, 0}, {1, 1, 3, -1.5, true, 0}, {2, 2, 3, 2.0, true, 0}};
  Network net(g, l);
  EXPECT_TRUE(net.single_pass());
  const auto out = net.query({0.3, 0.7, 1.0});
  EXPECT_DOUBLE_EQ(out[0], ssig(0.5 * 0.3 - 1.5 * 0.7 + 2.0));
}

TEST(Network, OutputWithoutLinksIsActivationOfZero) {
  const auto l = small_layout();
  Network net(base(l), l);
  EXPECT_EQ(net.query({1, 2, 3})[0], 0.0);
}

TEST(Network, DisabledLinksAreIgnored) {
  const auto l = small_layout();
  Genome g = base(l);
  g.links = {{0, 0, 3, 0.5, false, 0}};
  Network net(g, l);
  EXPECT_EQ(net.query({1, 0, 1})[0], 0.0);
}

// A chain input -> h1 -> h2 -> ... -> hk -> output of depth k+1, each with its own
// activation; the 10-update result equals one feed-forward pass when depth <= 10.
Genome chain(const GenomeLayout& l, int hidden, Rng& rng) {
  Genome g = base(l);
  int64_t innov = 0;
  int prev = 0;
  for (int h = 0; h < hidden; ++h) {
    const int id = l.first_hidden() + h;
    g.nodes.push_back({id, NodeKind::Hidden, static_cast<Activation>(h % 3)});
    g.links.push_back({innov++, prev, id, rng.uniform(-3, 3), true, 0});
    g.links.push_back({innov++, 2, id, rng.uniform(-3, 3), true, 0});  // bias into every node
    prev = id;
  }
  g.links.push_back({innov++, prev, 3, rng.uniform(-3, 3), true, 0});
  g.links.push_back({innov++, 1, 3, rng.uniform(-3, 3), true, 0});
  return g;
}

double feed_forward_chain(const Genome& g, const GenomeLayout& l, int hidden, const double* in) {
  // Hand-written single pass over the chain built above.
  double v = in[0];
  size_t k = 0;
  for (int h = 0; h < hidden; ++h) {
    const double s = g.links[k].weight * v + g.links[k + 1].weight * in[2];
    v = activate(static_cast<Activation>(h % 3), s);
    k += 2;
  }
  return activate(l.output_activation, g.links[k].weight * v + g.links[k + 1].weight * in[1]);
}

TEST(Network, TenUpdatesEqualFeedForwardPassUpToDepthTen) {
  const auto l = small_layout();
  Rng rng(3);
  for (int hidden = 0; hidden <= 9; ++hidden) {  // depth = hidden + 1 <= 10
    const Genome g = chain(l, hidden, rng);
    Network net(g, l);
    EXPECT_TRUE(net.single_pass()) << "hidden " << hidden;
    for (int t = 0; t < 20; ++t) {
      const double in[3] = {rng.uniform(-1, 1), rng.uniform(-1, 1), 1.0};
      double fast, sync;
      net.query(in, &fast);
      net.query_synchronous(in, &sync);
      const double ff = feed_forward_chain(g, l, hidden, in);
      EXPECT_EQ(fast, sync) << "single pass must be bit-identical to 10 updates";
      EXPECT_DOUBLE_EQ(sync, ff);
    }
  }
}

TEST(Network, DeeperThanTenUpdatesIsNotAFullPass) {
  const auto l = small_layout();
  Rng rng(4);
  const Genome g = chain(l, 12, rng);  // depth 13 > 10
  Network net(g, l);
  EXPECT_FALSE(net.single_pass());
  int differ = 0;
  for (int t = 0; t < 20; ++t) {
    const double in[3] = {rng.uniform(-1, 1), rng.uniform(-1, 1), 1.0};
    double out;
    net.query(in, &out);
    differ += out != feed_forward_chain(g, l, 12, in);
  }
  EXPECT_GT(differ, 0);
}

TEST(Network, RecurrentSelfLoopByHand) {
  // input0 -(w=1)-> h, h -(s=0.5)-> h, h -(v=2)-> output, h linear... use signed sigmoid.
  const auto l = small_layout();
  Genome g = base(l);
  const int h = l.first_hidden();
  g.nodes.push_back({h, NodeKind::Hidden, Activation::SignedSigmoid});
  g.links = {{0, 0, h, 1.0, true, 0}, {1, h, h, 0.5, true, 0}, {2, h, 3, 2.0, true, 0}};
  Network net(g, l);
  EXPECT_FALSE(net.single_pass());
  const double x = 0.8;
  // Synchronous updates: h_t = ssig(x + 0.5 h_{t-1}), o_t = ssig(2 h_{t-1}), all from 0.
  double hv = 0, ov = 0;
  for (int t = 0; t < 10; ++t) {
    const double nh = ssig(1.0 * x + 0.5 * hv);
    const double no = ssig(2.0 * hv);
    hv = nh;
    ov = no;
  }
  EXPECT_DOUBLE_EQ(net.query({x, 0, 1})[0], ov);
  // Reset before every query: the same query twice gives the same answer.
  EXPECT_EQ(net.query({x, 0, 1})[0], net.query({x, 0, 1})[0]);
}

TEST(Network, RejectsBadGenomes) {
  const auto l = small_layout();
  Genome g = base(l);
  g.links = {{0, 0, 9, 1.0, true, 0}};
  EXPECT_THROW(Network(g, l), std::invalid_argument);
  g.links = {{0, 3, 0, 1.0, true, 0}};  // into an input
  EXPECT_THROW(Network(g, l), std::invalid_argument);
  Genome h = base(l);
  h.nodes.pop_back();
  EXPECT_THROW(Network(h, l), std::invalid_argument);
  Network ok(base(l), l);
  EXPECT_THROW(ok.query(std::vector<double>{1.0}), std::invalid_argument);
}

TEST(Genome, CycleDetection) {
  const auto l = small_layout();
  Genome g = base(l);
  const int h = l.first_hidden();
  g.nodes.push_back({h, NodeKind::Hidden, Activation::Gaussian});
  g.nodes.push_back({h + 1, NodeKind::Hidden, Activation::Gaussian});
  g.links = {{0, 0, h, 1.0, true, 0}, {1, h, h + 1, 1.0, true, 0}, {2, h + 1, 3, 1.0, true, 0}};
  EXPECT_FALSE(has_cycle(g));
  g.links.push_back({3, h + 1, h, 1.0, true, 0});
  EXPECT_TRUE(has_cycle(g));
  g.links.back().enabled = false;
  EXPECT_FALSE(has_cycle(g));
  g.links.push_back({4, 3, 3, 1.0, true, 0});  // self-loop on the output
  EXPECT_TRUE(has_cycle(g));
}

}  // namespace
}  // namespace robozoo

namespace robozoo {
namespace {

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(Network, SkippingSettledNodesIsBitIdenticalToPlainUpdates) {
  // Recurrent robot CPPNs after NEAT mutations: the optimised synchronous
  // procedure must give exactly the plain one's bits, output by output.
  const GenomeLayout layout = robot_layout();
  NeatParams neat;
  RandomGenomeParams rp;
  rp.rounds = 40;
  Rng rng(17);
  int cyclic = 0;
  for (int t = 0; t < 60; ++t) {
    const Genome g = random_evolved_genome(layout, Regime::Recurrent, neat, rp, rng, t);
    cyclic += has_cycle(g);
    Network net(g, layout);
    for (int q = 0; q < 50; ++q) {
      double in[9];
      for (double& x : in) x = rng.uniform(-2, 2);
      double fast[11], plain[11];
      net.query_synchronous(in, fast);
      net.query_reference(in, plain);
      for (int o = 0; o < 11; ++o) ASSERT_TRUE(same_bits(fast[o], plain[o])) << "genome " << t << " output " << o;
    }
  }
  EXPECT_GT(cyclic, 20);  // the set really exercises cycles
}

}  // namespace
}  // namespace robozoo
