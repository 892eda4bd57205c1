// The primary test, Holm's family, the roles (by construction, descriptive),
// the paper's direction and the power at the paper's effect, on hand-made
// comparisons whose tests are worked out in ttest_test / holm_test / power_test.
#include "study/analysis/report/claim_verdicts.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "study/analysis/compare/holm.hpp"
#include "study/analysis/compare/power.hpp"

namespace robozoo {
namespace {

const ClaimRow& row(const ClaimsAssessment& c, const std::string& key) {
  for (const auto& r : c.rows)
    if (r.comparison.key == key) return r;
  throw std::logic_error("no row " + key);
}

ExperimentAnalysis hand_made(const std::vector<double>& ff_fitness, const std::vector<double>& rec_fitness) {
  ExperimentAnalysis a;
  a.control_arm = "feedforward";
  a.experimental_arm = "recurrent";
  a.last_generation = 29;
  a.fitness = {compare("best_fitness", "best-of-run fitness", "fitness units", ff_fitness, rec_fitness)};
  a.morphology = {
      // The paper: recurrent significantly fewer joints. Here fewer, strongly.
      compare("joints", "joints", "count", {10, 11, 12, 13}, {2, 3, 4, 5}),
      // The paper: no significant difference.
      compare("spheres", "spheres", "count", {3, 4, 5, 6}, {3, 4, 6, 6}),
      // The paper is silent.
      compare("time_sensors", "time sensors", "count", {1, 2, 3, 4}, {2, 3, 4, 6}),
      compare("hit_max_spheres", "at the cap", "share", {1, 1, 0, 1}, {0, 0, 1, 0}),
  };
  a.genotype = {compare("links", "links", "count", {99, 100, 101, 102}, {209, 210, 211, 215}),
                compare("recurrent_links", "recurrent links", "count", {0, 0, 0, 0}, {110, 111, 110, 112})};
  a.champion = {
      compare("topology_changed", "pooled share", "share", {0, 1, 1}, {1, 1, 1, 1, 0}, Samples::PooledEvents)};
  return a;
}

TEST(ClaimVerdicts, RolesAndHolmsFamily) {
  const ExperimentAnalysis a = hand_made({24, 25, 26, 27}, {28, 29, 30, 31});
  const ClaimsAssessment c = assess_claims(a);
  EXPECT_TRUE(c.paper_compared);
  EXPECT_EQ(row(c, "best_fitness").role, ClaimRole::Primary);
  EXPECT_EQ(row(c, "links").role, ClaimRole::ByConstruction);
  EXPECT_NE(row(c, "links").verdict.find("209 links, the feedforward start 99"), std::string::npos)
      << row(c, "links").verdict;
  EXPECT_EQ(row(c, "recurrent_links").role, ClaimRole::ByConstruction);
  EXPECT_EQ(row(c, "topology_changed").role, ClaimRole::Descriptive);
  EXPECT_EQ(row(c, "hit_max_spheres").role, ClaimRole::Descriptive);
  // The family: joints, spheres, time sensors.
  EXPECT_EQ(c.family_size, 3);
  const auto q = holm_adjust({row(c, "joints").comparison.student.p, row(c, "spheres").comparison.student.p,
                              row(c, "time_sensors").comparison.student.p});
  EXPECT_DOUBLE_EQ(row(c, "joints").holm_p, q[0]);
  EXPECT_DOUBLE_EQ(row(c, "spheres").holm_p, q[1]);
  EXPECT_DOUBLE_EQ(row(c, "time_sensors").holm_p, q[2]);
  EXPECT_TRUE(std::isnan(row(c, "best_fitness").holm_p));
  EXPECT_TRUE(std::isnan(row(c, "links").holm_p));
  // Joints: t = -8 / sqrt(5/3 * 1/2) = -8.76, p = 1.2e-4, times 3 still < 0.05: agrees.
  EXPECT_LT(row(c, "joints").holm_p, 0.05);
  EXPECT_EQ(row(c, "joints").direction, "same as the paper");
  EXPECT_EQ(row(c, "joints").verdict, "agrees: significant after Holm");
  // The paper's "significant" (p < 0.05 with 30 against 30) implies |d| >= 0.517; power with 4 against 4.
  EXPECT_NEAR(row(c, "joints").paper_effect, smallest_effect_for_p(0.05, 30, 30), 1e-12);
  EXPECT_NEAR(row(c, "joints").power, t_test_power(smallest_effect_for_p(0.05, 30, 30), 4, 4), 1e-12);
  // Spheres: the paper found no significant difference and neither does this.
  EXPECT_EQ(row(c, "spheres").verdict, "not significant after Holm, as in the paper (not a proof of equality)");
  EXPECT_TRUE(std::isnan(row(c, "spheres").power));
  EXPECT_EQ(row(c, "time_sensors").paper, "silent");
  EXPECT_EQ(row(c, "time_sensors").verdict, "not significant after Holm");
}

TEST(ClaimVerdicts, PrimaryReproducedOnlyWhenSignificantTheSameWay) {
  // Recurrent {28..31} against {24..27}: t = 4 / sqrt(5/3 / 2) = 4.38, df 6, p = 0.0047.
  ClaimsAssessment c = assess_claims(hand_made({24, 25, 26, 27}, {28, 29, 30, 31}));
  EXPECT_EQ(c.outcome, "reproduced");
  EXPECT_EQ(c.headline.rfind("The paper's fitness result (recurrent CPPNs fitter) is **reproduced** at generation 29 "
                             "(the last) with 4 feed-forward and 4 recurrent runs",
                             0),
            0u)
      << c.headline;
  // The paper's p < 0.001 with 30 against 30: |d| >= 0.895.
  EXPECT_NEAR(row(c, "best_fitness").paper_effect, 0.895002246349802, 1e-9);
  EXPECT_NE(c.headline.find("|d| ≥ 0.90"), std::string::npos);
  // Significant the other way.
  c = assess_claims(hand_made({28, 29, 30, 31}, {24, 25, 26, 27}));
  EXPECT_EQ(c.outcome, "not reproduced");
  EXPECT_EQ(row(c, "best_fitness").direction, "opposite to the paper");
  // Not significant, pointing the other way: inconclusive, and the headline says which way.
  c = assess_claims(hand_made({10, 12, 14}, {9, 11, 13}));
  EXPECT_EQ(c.outcome, "inconclusive");
  EXPECT_NE(c.headline.find("the estimate pointing the other way without significance"), std::string::npos)
      << c.headline;
  EXPECT_EQ(row(c, "best_fitness").verdict, "inconclusive: not significant, the estimate points the other way");
  // Equal means: no direction at all.
  c = assess_claims(hand_made({10, 12, 14}, {14, 12, 10}));
  EXPECT_EQ(c.outcome, "inconclusive");
  EXPECT_EQ(row(c, "best_fitness").direction, "");
  EXPECT_NE(c.headline.find("the estimate pointing neither way"), std::string::npos) << c.headline;
  // Too few runs for any test.
  c = assess_claims(hand_made({10}, {12}));
  EXPECT_EQ(c.outcome, "inconclusive");
  EXPECT_NE(c.headline.find("too few runs for the primary test"), std::string::npos) << c.headline;
}

TEST(ClaimVerdicts, ThePrimaryVerdictSaysWhenWelchDisagrees) {
  // The reduced experiment's fitness, 10 recurrent runs against 5 of the sparse
  // start as the control: Student's p = 0.0355 < 0.05, Welch's p = 0.0545 (ttest_test).
  ExperimentAnalysis a = hand_made({32.04415125, 23.59926401, 32.7971969, 29.61692114, 21.32281508},
                                   {17.63035334, 19.47156361, 21.99942461, 33.80974258, 20.44670961, 17.93723543,
                                    20.74533288, 22.11418172, 23.85350344, 18.30391089});
  a.control_arm = "recurrent-sparse";
  const ClaimsAssessment c = assess_claims(a);
  EXPECT_EQ(row(c, "best_fitness").verdict, "significant; Welch's test does not reach α");
  EXPECT_NE(c.headline.find("Welch's p = 0.055 (Welch's test, without equal variances, does not reach α)"),
            std::string::npos)
      << c.headline;
  // At 10 against 10 with similar spreads the two agree: no note.
  EXPECT_EQ(assess_claims(hand_made({24, 25, 26, 27}, {28, 29, 30, 31})).headline.find("without equal variances"),
            std::string::npos);
}

TEST(ClaimVerdicts, DirectionWithoutAnEffectSize) {
  // A run of one against nine: Student's test exists (df 8), d does not; constant
  // samples give t = inf, p = 0 and no d. The direction comes from the means.
  ExperimentAnalysis a = hand_made({24, 25, 26, 27}, {28, 29, 30, 31});
  a.champion = {compare("improvement_same_per_run", "gain, same topology", "fitness units",
                        {0.1, 0.2, 0.1, 0.2, 0.1, 0.2, 0.1, 0.2, 0.15}, {5.0}),
                compare("topology_changed_per_run", "share", "share", {0.5, 0.5}, {1.0, 1.0})};
  const ClaimsAssessment c = assess_claims(a);
  const ClaimRow& same = row(c, "improvement_same_per_run");
  EXPECT_TRUE(std::isnan(same.comparison.effect.d));
  EXPECT_EQ(same.comparison.student.df, 8.0);
  EXPECT_EQ(same.direction, "same as the paper");
  EXPECT_EQ(same.verdict, "agrees: significant after Holm");
  const ClaimRow& share = row(c, "topology_changed_per_run");
  EXPECT_EQ(share.comparison.student.p, 0.0);
  EXPECT_EQ(share.direction, "same as the paper");
  EXPECT_EQ(share.verdict, "agrees: significant after Holm");
}

TEST(ClaimVerdicts, ArmsThePaperDidNotCompare) {
  ExperimentAnalysis a = hand_made({24, 25, 26, 27}, {28, 29, 30, 31});
  a.control_arm = "recurrent-sparse";
  a.experimental_arm = "recurrent";
  const ClaimsAssessment c = assess_claims(a);
  EXPECT_FALSE(c.paper_compared);
  EXPECT_EQ(c.outcome, "");
  EXPECT_EQ(c.headline.rfind("The paper did not compare recurrent (sparse start) with recurrent CPPNs", 0), 0u)
      << c.headline;
  for (const auto& r : c.rows) {
    EXPECT_EQ(r.paper, "not compared by the paper");
    EXPECT_EQ(r.direction, "");
    EXPECT_TRUE(std::isnan(r.power));
  }
  // The sparse start has 99 links, the full one 209: by construction; neither is feed-forward, so
  // recurrent links are tested.
  EXPECT_EQ(row(c, "links").role, ClaimRole::ByConstruction);
  EXPECT_EQ(row(c, "recurrent_links").role, ClaimRole::Secondary);
  EXPECT_EQ(row(c, "joints").verdict, "significant after Holm");
}

TEST(ClaimVerdicts, OrientationAndConstruction) {
  EXPECT_EQ(paper_orientation("feedforward", "recurrent"), 1);
  EXPECT_EQ(paper_orientation("feedforward", "recurrent-zero"), 1);
  EXPECT_EQ(paper_orientation("recurrent-sparse", "feedforward"), -1);
  EXPECT_EQ(paper_orientation("recurrent", "recurrent-zero"), 0);
  EXPECT_EQ(by_construction("links", "recurrent", "recurrent-zero"), "");      // both start with 209
  EXPECT_EQ(by_construction("links", "feedforward", "recurrent-sparse"), "");  // both 99
  EXPECT_NE(by_construction("cycle_links", "recurrent-sparse", "feedforward"), "");
  EXPECT_EQ(by_construction("joints", "feedforward", "recurrent"), "");
  // Reversed arms: the paper's "recurrent fewer joints" reads "control fewer" here.
  ExperimentAnalysis a = hand_made({28, 29, 30, 31}, {24, 25, 26, 27});
  a.control_arm = "recurrent";
  a.experimental_arm = "feedforward";
  const ClaimsAssessment c = assess_claims(a);
  EXPECT_EQ(row(c, "joints").paper_direction, 1);
  EXPECT_EQ(row(c, "best_fitness").paper_direction, -1);
  EXPECT_EQ(c.outcome, "reproduced");  // recurrent (the control here) significantly fitter
}

}  // namespace
}  // namespace robozoo
