#include "evolve/neat/xor/xor_task.hpp"

#include <gtest/gtest.h>

#include "tests/evolve/neat/classic_params.hpp"

#include <cmath>

#include "evolve/neat/population.hpp"

namespace robozoo {
namespace {

Genome xor_base() {
  Genome g;
  g.id = 0;
  g.nodes = {{0, NodeKind::Input, Activation::Linear, 0.0},
             {1, NodeKind::Input, Activation::Linear, 0.0},
             {2, NodeKind::Bias, Activation::Linear, 0.0},
             {3, NodeKind::Output, Activation::SignedSigmoid, 1.0}};
  return g;
}

double logistic(double x) { return 1.0 / (1.0 + std::exp(-x)); }

TEST(XorTask, HandMadeSolution) {
  // h = gaussian(x1 - x2) is 1 on (0,0), (1,1) and e^-1 on the others;
  // out = ssig(-5 h + 3.4 * bias), so the mapped output is logistic(-5 h + 3.4).
  Genome g = xor_base();
  g.nodes.push_back({4, NodeKind::Hidden, Activation::Gaussian});
  g.links = {{0, 0, 4, 1.0, true, 0}, {1, 1, 4, -1.0, true, 0}, {2, 2, 3, 3.4, true, 0}, {3, 4, 3, -5.0, true, 0}};
  const XorResult r = evaluate_xor(g);
  EXPECT_TRUE(r.solved);
  const double same = logistic(-5.0 + 3.4), diff = logistic(-5.0 * std::exp(-1.0) + 3.4);
  EXPECT_NEAR(r.outputs[0], same, 1e-12);
  EXPECT_NEAR(r.outputs[1], diff, 1e-12);
  EXPECT_NEAR(r.outputs[2], diff, 1e-12);
  EXPECT_NEAR(r.outputs[3], same, 1e-12);
  const double err = 2 * same + 2 * (1 - diff);
  EXPECT_NEAR(r.fitness, (4 - err) * (4 - err), 1e-12);
}

TEST(XorTask, NoHiddenNodeNeverSolvesXor) {
  // One signed-sigmoid unit of x1, x2 and the bias is linearly separable only.
  NeatParams p = classic_neat();
  Rng rng(1);
  for (int i = 0; i < 2000; ++i) {
    Genome g = initial_genome(xor_layout(), i, p, Regime::FeedForward, rng);
    for (auto& l : g.links) l.weight = rng.uniform(-5, 5);
    const XorResult r = evaluate_xor(g);
    ASSERT_FALSE(r.solved);
    ASSERT_GE(r.fitness, 0.0);
    ASSERT_LE(r.fitness, 16.0);
  }
}

TEST(XorTask, OutputsOfZeroNetInputScoreFour) {
  Genome g = xor_base();  // no links: output ssig(0) = 0, mapped 0.5 everywhere
  const XorResult r = evaluate_xor(g);
  EXPECT_FALSE(r.solved);
  EXPECT_DOUBLE_EQ(r.fitness, 4.0);
}

TEST(XorTask, NeatSolvesXorInBothRegimes) {
  for (Regime regime : {Regime::FeedForward, Regime::Recurrent}) {
    NeatParams p = classic_neat();
    Rng rng(1);
    Population pop(p, regime, xor_layout(), rng);
    bool solved = false;
    for (int gen = 0; gen < 200 && !solved; ++gen) {
      std::vector<double> f;
      for (const auto& g : pop.genomes()) {
        const XorResult r = evaluate_xor(g);
        f.push_back(r.fitness);
        solved |= r.solved;
      }
      if (!solved) pop.advance(f, rng);
    }
    EXPECT_TRUE(solved) << (regime == Regime::FeedForward ? "feed-forward" : "recurrent");
  }
}

// Stanley's own evaluation (XorRules), on the NEAT paper's steepened-sigmoid layout.
GenomeLayout steep_layout() { return xor_layout(Activation::SteepenedSigmoid); }
Genome steep_base() {
  Genome g = xor_base();
  g.nodes[3].activation = Activation::SteepenedSigmoid;
  return g;
}

TEST(StanleyXor, UnreachedNodesOutputZero) {
  // Hidden 4 has only a disabled in-link; 4 -> out weight 2, bias -> out -1. The project's query
  // gives node 4 sigmoid(0) = 0.5, so the output's sum is 0 and it reads 0.5; Stanley's node 4
  // never turns on: sum -1, output 1 / (1 + e^4.9).
  Genome g = steep_base();
  g.nodes.push_back({4, NodeKind::Hidden, Activation::SteepenedSigmoid, 0.5});
  g.links = {{0, 0, 4, 1.0, false, 0}, {1, 2, 3, -1.0, true, 0}, {2, 4, 3, 2.0, true, 0}};
  const XorResult plain = evaluate_xor(g, steep_layout());
  XorRules stanley;
  stanley.stanley_activation = true;
  const XorResult s = evaluate_xor(g, steep_layout(), stanley);
  for (int k = 0; k < 4; ++k) {
    EXPECT_DOUBLE_EQ(plain.outputs[static_cast<size_t>(k)], 0.5);
    EXPECT_DOUBLE_EQ(s.outputs[static_cast<size_t>(k)], 1.0 / (1.0 + std::exp(4.9)));
  }
  // No input reaches the output at all: Stanley's flawed network, fitness 0.001.
  g.links[1].enabled = false;
  const XorResult flawed = evaluate_xor(g, steep_layout(), stanley);
  EXPECT_EQ(flawed.fitness, 0.001);
  EXPECT_FALSE(flawed.solved);
}

TEST(StanleyXor, DeepNetworksAreRelaxedToTheirSteadyState) {
  // x1 -> h1 -> ... -> h12 -> out, weights 10, every node also bias -> node -5: each node is
  // about 1 when its predecessor is 1, about 0 when it is 0, so the chain carries x1 to the output
  // 13 links down. Steady state on (1, 0): v = s(10 v - 5) iterated 13 times from x1 = 1. The
  // project's 10 synchronous updates from all-zero nodes leave h11, h12 and the output on the
  // zero wave: the output is near 0.
  Genome g = steep_base();
  int32_t prev = 0;
  int64_t innovation = 0;
  for (int k = 0; k < 12; ++k) {
    const int32_t id = 4 + k;
    g.nodes.push_back({id, NodeKind::Hidden, Activation::SteepenedSigmoid, 0.5});
    g.links.push_back({innovation++, prev, id, 10.0, true, 0});
    g.links.push_back({innovation++, 2, id, -5.0, true, 0});
    prev = id;
  }
  g.links.push_back({innovation++, prev, 3, 10.0, true, 0});
  g.links.push_back({innovation++, 2, 3, -5.0, true, 0});
  auto s = [](double x) { return 1.0 / (1.0 + std::exp(-4.9 * x)); };
  double v = 1.0;
  for (int k = 0; k < 13; ++k) v = s(10.0 * v - 5.0);
  XorRules stanley;
  stanley.stanley_activation = true;
  EXPECT_NEAR(evaluate_xor(g, steep_layout(), stanley).outputs[2], v, 1e-12);
  EXPECT_GT(v, 0.99);
  EXPECT_LT(evaluate_xor(g, steep_layout()).outputs[2], 0.01)
      << "10 synchronous updates do not reach the steady state of a 13-deep chain";
}

TEST(StanleyXor, HalfCountsAsOne) {
  // h = AND(x1, x2) exactly (its sums are +-200 or below -600: the sigmoid saturates to 1 or 0);
  // out sum = x1 + x2 - 2h - bias: -1, 0, 0, -1. Outputs 0.5 on (0,1) and (1,0): a 1 only with
  // Stanley's test (out >= 0.5).
  Genome g = steep_base();
  g.nodes.push_back({4, NodeKind::Hidden, Activation::SteepenedSigmoid, 0.5});
  g.links = {{0, 0, 4, 400.0, true, 0}, {1, 1, 4, 400.0, true, 0}, {2, 2, 4, -600.0, true, 0}, {3, 0, 3, 1.0, true, 0},
             {4, 1, 3, 1.0, true, 0},   {5, 2, 3, -1.0, true, 0},  {6, 4, 3, -2.0, true, 0}};
  XorRules half;
  half.half_is_one = true;
  const XorResult r = evaluate_xor(g, steep_layout(), half);
  EXPECT_EQ(r.outputs[1], 0.5);
  EXPECT_EQ(r.outputs[2], 0.5);
  EXPECT_TRUE(r.solved);
  EXPECT_FALSE(evaluate_xor(g, steep_layout()).solved);
}

}  // namespace
}  // namespace robozoo
