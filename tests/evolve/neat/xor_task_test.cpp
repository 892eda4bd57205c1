#include "evolve/neat/xor_task.hpp"

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
  g.links = {{0, 0, 4, 1.0, true, 0}, {1, 1, 4, -1.0, true, 0}, {2, 2, 3, 3.4, true, 0},
             {3, 4, 3, -5.0, true, 0}};
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

}  // namespace
}  // namespace robozoo
