#include "evolve/cppn/network.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "evolve/core/rng.hpp"
#include "evolve/cppn/random_genome.hpp"
#include "evolve/neat/start/random_genome.hpp"

#include <cstring>
#include "tests/evolve/neat/tiny_genome.hpp"

namespace robozoo {
namespace {

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
  const auto l = test::tiny_layout();
  Genome g = base(l);
  g.links = {{0, 0, 3, 0.5, true, 0}, {1, 1, 3, -1.5, true, 0}, {2, 2, 3, 2.0, true, 0}};
  Network net(g, l);
  EXPECT_TRUE(net.single_pass());
  const auto out = net.query({0.3, 0.7, 1.0});
  EXPECT_DOUBLE_EQ(out[0], ssig(0.5 * 0.3 - 1.5 * 0.7 + 2.0));
}

TEST(Network, OutputWithoutLinksIsActivationOfZero) {
  const auto l = test::tiny_layout();
  Network net(base(l), l);
  EXPECT_EQ(net.query({1, 2, 3})[0], 0.0);
}

TEST(Network, DisabledLinksAreIgnored) {
  const auto l = test::tiny_layout();
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
  const auto l = test::tiny_layout();
  Rng rng(3);
  for (int hidden = 0; hidden <= 9; ++hidden) {  // depth = hidden + 1 <= 10
    const Genome g = chain(l, hidden, rng);
    Network net(g, l);
    EXPECT_TRUE(net.single_pass()) << "hidden " << hidden;
    for (int t = 0; t < 20; ++t) {
      const double in[3] = {rng.uniform(-1, 1), rng.uniform(-1, 1), 1.0};
      double fast, sync;
      net.query(in, &fast);
      net.query_reference(in, &sync);
      const double ff = feed_forward_chain(g, l, hidden, in);
      EXPECT_EQ(fast, sync) << "single pass must be bit-identical to 10 updates";
      EXPECT_DOUBLE_EQ(sync, ff);
    }
  }
}

TEST(Network, DeeperThanTenUpdatesIsNotAFullPass) {
  const auto l = test::tiny_layout();
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
  const auto l = test::tiny_layout();
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
  const auto l = test::tiny_layout();
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
  const auto l = test::tiny_layout();
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

// Batches shaped like growth's: a cloud (x, y on a circle, z = 0, r_parent and
// bias the same at every point, no one-hot), weight queries (midpoints, r_parent
// 0, one-hots that differ from point to point), and points with every input random.
QueryArray cloud_batch(int n, double r, Rng& rng) {
  QueryArray in = QueryArray::Zero(9, n);
  const double cx = rng.uniform(-1, 1), cy = rng.uniform(-1, 1);
  for (int k = 0; k < n; ++k) {
    in(0, k) = cx + r * std::cos(0.0628 * k);
    in(1, k) = cy + r * std::sin(0.0628 * k);
    in(3, k) = r;
    in(4, k) = 1.0;
  }
  return in;
}

QueryArray weight_batch(int n, Rng& rng) {
  QueryArray in = QueryArray::Zero(9, n);
  for (int k = 0; k < n; ++k) {
    in(0, k) = rng.uniform(-1, 1);
    in(1, k) = rng.uniform(-1, 1);
    in(4, k) = 1.0;
    const int one_hot = static_cast<int>(rng.uniform_int(-1, 3));
    if (one_hot >= 0) in(5 + one_hot, k) = 1.0;
  }
  return in;
}

QueryArray random_batch(int n, Rng& rng) {
  QueryArray in(9, n);
  for (int i = 0; i < 9; ++i)
    for (int k = 0; k < n; ++k) in(i, k) = rng.uniform(-2, 2);
  return in;
}

/// Same bits, or both NaN: which NaN's sign and payload an addition passes on
/// depends on the order of its operands, which the compiler may choose either way
/// (IEEE addition commutes); growth reads every NaN output as 0.
bool same_value(double a, double b) { return same_bits(a, b) || (std::isnan(a) && std::isnan(b)); }

/// Every output of every point of the batch, bit for bit against the plain
/// per-point procedure; false (with a message) at the first difference.
::testing::AssertionResult batch_matches_reference(Network& net, const QueryArray& in, bool synchronous) {
  QueryArray out(11, in.cols());
  if (synchronous)
    net.query_batch_synchronous(in, out);
  else
    net.query_batch(in, out);
  for (int k = 0; k < in.cols(); ++k) {
    double point[9], want[11];
    for (int i = 0; i < 9; ++i) point[i] = in(i, k);
    net.query_reference(point, want);
    for (int o = 0; o < 11; ++o)
      if (!same_value(out(o, k), want[o]))
        return ::testing::AssertionFailure() << "point " << k << " of " << in.cols() << ", output " << o << ": batch "
                                             << out(o, k) << ", per point " << want[o];
  }
  return ::testing::AssertionSuccess();
}

struct BatchCounts {
  int genomes = 0, cyclic = 0, single_pass = 0, non_finite = 0, nan = 0;
};

void check_genome(const Genome& g, Rng& rng, BatchCounts& counts) {
  Network net(g, robot_layout());
  ++counts.genomes;
  counts.cyclic += has_cycle(g);
  counts.single_pass += net.single_pass();
  // Sizes around the block size, so full, partial and several blocks are covered.
  const int sizes[] = {1, 37, Network::kBlockPoints, Network::kBlockPoints + 1, 100};
  const int n = sizes[rng.uniform_int(0, 4)];
  const QueryArray batches[] = {cloud_batch(n, rng.uniform(0.02, 0.3), rng), weight_batch(n, rng),
                                random_batch(n, rng)};
  for (const QueryArray& in : batches) {
    ASSERT_TRUE(batch_matches_reference(net, in, false)) << "genome " << counts.genomes;
    if (net.single_pass()) {
      ASSERT_TRUE(batch_matches_reference(net, in, true)) << "genome " << counts.genomes;
    }
  }
  QueryArray out(11, n);
  for (const QueryArray& in : batches) {
    net.query_batch(in, out);
    counts.non_finite += !out.isFinite().all();
    counts.nan += out.isNaN().any();
  }
}

TEST(Network, BatchedQueriesAreBitIdenticalToThePerPointProcedure) {
  // Thousands of genomes: NEAT-evolved of both regimes, fully recurrent starts
  // (cycles through every output, all 10 updates needed), and random CPPNs whose
  // hidden nodes may be linear or sine (unbounded loops: infinities and NaNs).
  const GenomeLayout layout = robot_layout();
  NeatParams neat;
  Rng rng(2024);
  BatchCounts ff, rec, full, wild;
  NeatParams sparse = neat;  // recurrent links only as mutations add them
  sparse.initial_links = InitialLinks::InputsToOutputs;
  for (int t = 0; t < 800; ++t) {
    RandomGenomeParams rp;
    rp.rounds = static_cast<int>(rng.uniform_int(0, 60));
    check_genome(random_evolved_genome(layout, Regime::FeedForward, neat, rp, rng, t), rng, ff);
    check_genome(random_evolved_genome(layout, Regime::Recurrent, sparse, rp, rng, t), rng, rec);
    rp.rounds = static_cast<int>(rng.uniform_int(0, 30));
    check_genome(random_evolved_genome(layout, Regime::Recurrent, neat, rp, rng, t), rng, full);
    if (HasFatalFailure()) return;
  }
  for (int t = 0; t < 600; ++t) {
    Genome g = random_cppn(layout, rng.bernoulli(0.7), static_cast<int>(rng.uniform_int(0, 8)),
                           static_cast<int>(rng.uniform_int(0, 40)), rng);
    for (auto& node : g.nodes)
      if (node.kind == NodeKind::Hidden) node.activation = static_cast<Activation>(rng.uniform_int(0, 4));
    for (auto& link : g.links)  // some huge weights: sums overflow to infinities, cos and sin give NaNs
      if (rng.bernoulli(0.25)) link.weight *= std::pow(10.0, static_cast<double>(rng.uniform_int(10, 300)));
    check_genome(g, rng, wild);
    if (HasFatalFailure()) return;
  }
  EXPECT_EQ(ff.cyclic, 0);
  EXPECT_GT(ff.single_pass, 400);  // (single-pass networks are also checked on the forced synchronous path)
  EXPECT_GT(rec.cyclic, 200);
  EXPECT_EQ(full.cyclic, 800);
  EXPECT_EQ(full.single_pass, 0);
  EXPECT_GT(wild.non_finite, 5);  // the huge weights really reach infinities and NaNs
  EXPECT_GT(wild.nan, 5);
}

TEST(Network, BatchRejectsWrongShapes) {
  NeatParams neat;
  Rng rng(1);
  Network net(random_evolved_genome(robot_layout(), Regime::Recurrent, neat, RandomGenomeParams{}, rng, 0),
              robot_layout());
  QueryArray in = QueryArray::Zero(9, 3), out(11, 3), short_out(11, 2), wide_in = QueryArray::Zero(8, 3);
  EXPECT_THROW(net.query_batch(in, short_out), std::invalid_argument);
  EXPECT_THROW(net.query_batch(wide_in, out), std::invalid_argument);
  QueryArray none(9, 0), none_out(11, 0);
  net.query_batch(none, none_out);  // an empty batch is no query
  EXPECT_EQ(net.queries(), 0);
  net.query_batch(in, out);
  EXPECT_EQ(net.queries(), 3);
}

}  // namespace
}  // namespace robozoo
