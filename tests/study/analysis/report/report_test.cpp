#include "study/analysis/report/report.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "study/analysis/read/log_results.hpp"
#include "study/analysis/report/paper_claims.hpp"
#include "tests/study/analysis/hand_made_experiment.hpp"
#include "tests/support/subprocess.hpp"

namespace robozoo {
namespace {

ReportInputs inputs() {
  ReportInputs in;
  in.source = "runs/x";
  in.analysis.last_generation = 2;
  in.analysis.fitness = {compare("best_fitness", "best-of-run fitness", "fitness units", {10, 11, 12}, {20, 21, 22})};
  in.analysis.morphology = {compare("joints", "joints", "count", {3, 4, 5}, {3, 4, 5}),
                            compare("spheres", "spheres", "count", {3, 4, 5}, {13, 14, 15})};
  in.analysis.morphology[1].control_at_cap = 3;
  in.analysis.morphology[1].experimental_at_cap = 1;
  in.analysis.genotype = {compare("links", "links (enabled)", "count", {99, 100, 101}, {209, 210, 212})};
  in.analysis.champion = {
      compare("topology_changed_per_run", "share of a run's new champions with another topology (per run)", "share",
              {0.5, 0.6, 0.7}, {0.9, 1.0, 0.8}),
      compare("topology_changed", "new champions with another topology (pooled)", "share", {0, 1, 0, 1}, {1, 1, 1, 0},
              Samples::PooledEvents)};
  CurvePoint p;
  for (int g = 0; g < 6; ++g) {
    p.generation = g;
    p.student.p = g == 1 || g == 2 || g == 4 ? 0.01 : 0.3;
    in.analysis.fitness_curve.push_back(p);
  }
  in.fitness_png = "fig1_fitness.png";
  in.zoo = {{"feed-forward", "", "robozoo-render is missing"}, {"recurrent", "zoo-recurrent.png", "made"}};
  in.commands = {"build/bin/robozoo-stats runs/x"};
  return in;
}

TEST(Report, HeadlineFirstThenTheTestsThenTheClaims) {
  const std::string md = markdown_report(inputs());
  // Recurrent {20, 21, 22} against {10, 11, 12}: t = 10 / sqrt(1 * 2/3) = 12.25, df 4.
  const size_t headline = md.find(
      "The paper's fitness result (recurrent CPPNs fitter) is **reproduced** at "
      "generation 2 (the last) with 3 feed-forward and 3 recurrent runs");
  const size_t tests = md.find("## The tests, fixed before the data");
  const size_t claims = md.find("## The paper's claims beside robozoo's figures");
  ASSERT_NE(headline, std::string::npos) << md;
  EXPECT_LT(headline, md.find("Logs: `runs/x`"));
  EXPECT_LT(headline, tests);
  EXPECT_LT(tests, claims);
  EXPECT_NE(md.find("Student's t(4) = 12.25, p < 0.001"), std::string::npos) << md;
  // The secondary family: joints, spheres and the per-run share (links: by construction; pooled: descriptive).
  EXPECT_NE(md.find("the other 3 statistics whose samples are runs"), std::string::npos) << md;
}

TEST(Report, ClaimsTableHasThePaperTheEffectHolmPowerAndVerdict) {
  const std::string md = markdown_report(inputs());
  EXPECT_NE(md.find("| statistic | the paper (recurrent vs feed-forward) | feed-forward (mean ± s.e., n) | recurrent "
                    "(mean ± s.e., n) | Cohen's d [95 % CI] | Student's p | Holm's p | power at the paper's effect | "
                    "direction | verdict |"),
            std::string::npos)
      << md;
  // The primary row: d = 10 / 1 = 10 with its interval, power at d = 0.90 with 3 against 3.
  EXPECT_NE(md.find("| **primary:** best-of-run fitness | recurrent fitter: p < 0.001"), std::string::npos) << md;
  EXPECT_NE(md.find("| 11.00 ± 0.58 (3) | 21.00 ± 0.58 (3) | 10.00 ["), std::string::npos) << md;
  EXPECT_NE(md.find("(at d = 0.90) | same as the paper | agrees: significant |"), std::string::npos) << md;
  // The paper's "recurrent significantly fewer joints": d = -0.52 in this direction.
  EXPECT_NE(md.find(" (at d = -0.52) | — | inconclusive"), std::string::npos) << md;
  // Joints: equal samples, t = 0: inconclusive after Holm, no direction.
  EXPECT_NE(md.find("| 4.00 ± 0.58 (3) | 4.00 ± 0.58 (3) | 0.00 ["), std::string::npos) << md;
  EXPECT_NE(md.find("| — | inconclusive: not significant after Holm |"), std::string::npos) << md;
  // Spheres: censored, and the counts beside the statistic.
  EXPECT_NE(md.find("spheres (censored: 3 of 3 feed-forward and 1 of 3 recurrent best-of-run robots at "
                    "max_spheres)"),
            std::string::npos)
      << md;
  // Links: true by construction, no test in the family.
  EXPECT_NE(md.find("true by construction: the recurrent start has 209 links, the feedforward start 99 |"),
            std::string::npos)
      << md;
  // Pooled events never appear in the claims table, and are described, not tested, below.
  EXPECT_EQ(md.find("| new champions with another topology (pooled) | 96.99"), std::string::npos);
  EXPECT_NE(md.find("| — | — | — | pooled events: descriptive |"), std::string::npos) << md;
}

TEST(Report, ArmsThePaperDidNotCompareHaveNoPaperColumn) {
  ReportInputs in = inputs();
  in.analysis.control_arm = "recurrent-sparse";
  in.analysis.experimental_arm = "recurrent";
  const std::string md = markdown_report(in);
  EXPECT_EQ(md.find("the paper (recurrent vs feed-forward)"), std::string::npos) << md;
  EXPECT_EQ(md.find("| agrees"), std::string::npos) << md;
  EXPECT_EQ(md.find("paper's way"), std::string::npos) << md;
  EXPECT_EQ(md.find("| direction |"), std::string::npos) << md;
  EXPECT_NE(md.find("The paper compared feed-forward with recurrent CPPNs only; it says nothing about recurrent "
                    "(sparse start) against recurrent"),
            std::string::npos)
      << md;
  EXPECT_EQ(md.rfind("# robozoo", 0), 0u);
  EXPECT_NE(md.find("The paper did not compare recurrent (sparse start) with recurrent CPPNs"), std::string::npos);
}

TEST(Report, FigureOneMarksTheSignificantGenerations) {
  const std::string md = markdown_report(inputs());
  EXPECT_NE(md.find("p < 0.05 (uncorrected, descriptive; the primary test is the last generation's): 1-2, 4."),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| Student's t, df, p | Welch's t, df, p | Cohen's d [95 % CI] |"), std::string::npos);
  // Fitness: Student's and Welch's t side by side; equal n and variances: the same t, Welch's df 4 too.
  EXPECT_NE(md.find("| 12.25, 4, < 0.001 | 12.25, 4, < 0.001 |"), std::string::npos) << md;
}

TEST(Report, OtherArmsAgainstTheControlAreOneHolmFamily) {
  ReportInputs in = inputs();
  RunAnalysis r;
  in.analysis.control.push_back(r);
  // recurrent-zero {25, 27} against {20, 22}: t = 5 / sqrt(2) = 3.54, df 2, p = 0.0715;
  // recurrent-sparse {40, 41, 42} against {10, 11, 12}: t = 36.74, df 4, p < 0.001.
  in.analysis.other_arms = {
      {"recurrent-sparse", compare("best_fitness", "f", "fitness units", {10, 11, 12}, {40, 41, 42})},
      {"recurrent-zero", compare("best_fitness", "f", "fitness units", {20, 22}, {25, 27})}};
  const std::string md = markdown_report(in);
  ASSERT_NE(md.find("### Other arms against the control"), std::string::npos) << md;
  // Holm over the two: 2 x p(sparse) < 0.001; max(that, 1 x 0.0715) = 0.0715.
  const double p_zero = ttest_ind({25, 27}, {20, 22}).p;
  EXPECT_NE(md.find("| recurrent (zero-weight start) | 21.00 ± 1.00 (2) | 26.00 ± 1.00 (2) | 3.54, 2, " +
                    format_p(p_zero) + " | 3.54, 2, " + format_p(p_zero) + " | 3.54 ["),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| " + format_p(p_zero) + " | recurrent fitter; here the same way, not significant after Holm |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("recurrent fitter; here the same way, significant after Holm |"), std::string::npos) << md;
}

TEST(Report, FiguresZooAndCommands) {
  ReportInputs in = inputs();
  in.analysis.control_arm = "feedforward";
  in.analysis.experimental_arm = "recurrent-sparse";
  RunAnalysis r;
  r.max_d = 7.25;
  in.analysis.experimental.push_back(r);
  in.target_distance = 50;
  in.outcome_pngs = {"outcomes-feedforward.png"};
  const std::string md = markdown_report(in);
  EXPECT_NE(md.find("| feed-forward (mean ± s.e., n) | recurrent (sparse start) (mean ± s.e., n) |"), std::string::npos)
      << md;
  EXPECT_NE(md.find("7.250 m (recurrent (sparse start))"), std::string::npos) << md;
  EXPECT_NE(md.find("of the 50.0 m from the start to the target: fitness did not come near its ceiling"),
            std::string::npos);
  EXPECT_NE(md.find("![outcome shares](outcomes-feedforward.png)"), std::string::npos);
  EXPECT_NE(md.find("![Figure 1](fig1_fitness.png)"), std::string::npos);
  EXPECT_NE(md.find("**feed-forward**: robozoo-render is missing"), std::string::npos);
  EXPECT_NE(md.find("![recurrent zoo](zoo-recurrent.png)"), std::string::npos);
  EXPECT_NE(md.find("```sh\nbuild/bin/robozoo-stats runs/x\n```"), std::string::npos);
}

TEST(Report, HandMadeExperimentEndToEnd) {
  // The four hand-made runs (hand_made_experiment.hpp), read, analysed and reported.
  testing::TempDir dir;
  testing::write_hand_made_experiment(dir.path);
  std::vector<RunAnalysis> runs;
  for (const char* name : {"feedforward-s1", "feedforward-s2", "recurrent-s1", "recurrent-s2"})
    runs.push_back(analyze_run(summarize_run_file(dir / (std::string(name) + ".lcmlog"))));
  ReportInputs in;
  in.analysis = analyze_experiment(runs);
  const std::string md = markdown_report(in);
  // Fitness: recurrent {18, 16.5} against feed-forward {16, 17}: s_p^2 = 1.625 / 2, t = 0.75 / sqrt(0.8125)
  // = 0.83, df 2, p = 1 - t / sqrt(t^2 + 2) = 0.493; Welch df = 0.8125^2 / (0.5625^2 + 0.25^2) = 1.74.
  const double t = 0.75 / std::sqrt(0.8125);
  EXPECT_NEAR(1 - t / std::sqrt(t * t + 2), 0.4929, 1e-4);
  EXPECT_NE(md.find("is **inconclusive** at generation 2 (the last) with 2 feed-forward and 2 recurrent runs: "
                    "feed-forward 16.50 ± 0.50, recurrent 17.25 ± 0.75 (mean ± s.e.), Student's t(2) = 0.83, "
                    "p = 0.493"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| 16.50 ± 0.50 (2) | 17.25 ± 0.75 (2) | 0.83, 2, 0.493 | 0.83, 1.7, 0.504 | 0.83 ["),
            std::string::npos)
      << md;
  // Per-run share of topology-changing new champions: feed-forward {0, 1}, recurrent {1, 0.5}.
  EXPECT_NE(md.find("| 50.00 ± 50.00 % (2) | 75.00 ± 25.00 % (2) |"), std::string::npos) << md;
  // Pooled events: {0, 1} and {1, 1, 1, 0}, described only.
  EXPECT_NE(md.find("| 50.00 ± 50.00 % (2) | 75.00 ± 25.00 % (4) | — | — | — | pooled events: descriptive |"),
            std::string::npos)
      << md;
}

TEST(Report, Formatting) {
  EXPECT_EQ(format_p(0.0004), "< 0.001");
  EXPECT_EQ(format_p(0.0234), "0.023");
  EXPECT_EQ(format_p(std::nan("")), "n/a");
  EXPECT_EQ(format_mean_se(describe({0.05, 0.06})), "0.0550 ± 0.0050");
  EXPECT_EQ(format_mean_se(describe({})), "n/a");
}

TEST(PaperClaims, EveryClaimIsAboutAStatisticTheAnalysisComputes) {
  // The champion-change figures are claims about the per-run statistics (tested), not the pooled ones.
  const PaperClaim* c = paper_claim("topology_changed_per_run");
  ASSERT_NE(c, nullptr);
  EXPECT_NE(c->paper.find("96.99"), std::string::npos);
  EXPECT_FALSE(c->run_samples);
  EXPECT_EQ(paper_claim("topology_changed"), nullptr);
  EXPECT_EQ(paper_claim("time_sensors"), nullptr);  // silent
  EXPECT_EQ(paper_claim("best_fitness")->p_bound, 0.001);
  for (const auto& claim : paper_claims()) EXPECT_TRUE(claim.direction >= -1 && claim.direction <= 1) << claim.key;
}

}  // namespace
}  // namespace robozoo
