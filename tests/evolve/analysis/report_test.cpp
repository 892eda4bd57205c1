#include "evolve/analysis/report.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "evolve/analysis/paper_claims.hpp"

namespace robozoo {
namespace {

ReportInputs inputs() {
  ReportInputs in;
  in.source = "runs/x";
  in.analysis.fitness = {compare("best_fitness", "best-of-run fitness", "fitness units", {10, 11, 12}, {20, 21, 22})};
  in.analysis.morphology = {compare("joints", "joints", "count", {3, 4, 5}, {3, 4, 5}),
                            compare("spheres", "spheres", "count", {3, 4, 5}, {13, 14, 15})};
  in.analysis.champion = {compare("topology_changed", "new champions with another topology", "share", {0, 1, 0, 1},
                                  {1, 1, 1, 0})};
  in.fitness_png = "fig1_fitness.png";
  in.zoo = {{"feed-forward", "", "robozoo-render is missing"}, {"recurrent", "zoo-recurrent.png", "made"}};
  in.commands = {"build/bin/robozoo-stats runs/x"};
  return in;
}

TEST(Report, PutsEachClaimBesideRobozoosFigure) {
  const std::string md = markdown_report(inputs());
  // The fitness claim: recurrent fitter, significantly; here 21 vs 11 with p < 0.001.
  EXPECT_NE(md.find("| best-of-run fitness | recurrent significantly fitter"), std::string::npos) << md;
  EXPECT_NE(md.find("| 11.00 ± 0.58 | 21.00 ± 0.58 | < 0.001 *** | yes, significant |"), std::string::npos) << md;
  // Joints: the paper finds fewer with recurrent CPPNs; equal samples here give t = 0, p = 1:
  // the data cannot decide.
  EXPECT_NE(md.find("| 4.00 ± 0.58 | 4.00 ± 0.58 | 1.000  | inconclusive (p ≥ 0.05) |"), std::string::npos)
      << md;
  // Spheres: "not significant" in the paper, strongly different here.
  EXPECT_NE(md.find("no: robozoo finds a significant difference"), std::string::npos);
  // The share in per cent, beside the paper's 96.99 % vs 59.92 %.
  EXPECT_NE(md.find("96.99 % (recurrent) vs 59.92 % (feed-forward), p < 0.001 | 50.00 ± 28.87 % | 75.00 ± 25.00 %"),
            std::string::npos)
      << md;
  // Claims whose statistic is absent are left out.
  EXPECT_EQ(md.find("forward links"), std::string::npos);
  // Figures, zoo sheets (present and missing), reproduction commands.
  EXPECT_NE(md.find("![Figure 1](fig1_fitness.png)"), std::string::npos);
  EXPECT_NE(md.find("**feed-forward**: robozoo-render is missing"), std::string::npos);
  EXPECT_NE(md.find("![recurrent zoo](zoo-recurrent.png)"), std::string::npos);
  EXPECT_NE(md.find("```sh\nbuild/bin/robozoo-stats runs/x\n```"), std::string::npos);
}

TEST(Report, WithoutSignificanceNothingAgreesOrDisagrees) {
  ReportInputs in = inputs();
  // Recurrent fitter, as the paper says, but not significantly (p about 0.4).
  in.analysis.fitness = {compare("best_fitness", "best-of-run fitness", "fitness units", {10, 12, 14}, {11, 13, 15})};
  // Spheres: the paper finds no significant difference, and neither does this sample.
  in.analysis.morphology = {compare("spheres", "spheres", "count", {3, 4, 5}, {3, 4, 6})};
  in.analysis.control_arm = "feedforward";
  in.analysis.experimental_arm = "recurrent";
  const std::string md = markdown_report(in);
  EXPECT_EQ(md.find("| yes"), std::string::npos) << md;
  EXPECT_EQ(md.find("same direction"), std::string::npos) << md;
  size_t n = 0;
  for (size_t at = md.find("inconclusive (p ≥ 0.05)"); at != std::string::npos;
       at = md.find("inconclusive (p ≥ 0.05)", at + 1))
    ++n;
  EXPECT_EQ(n, 3u) << md;  // fitness, spheres and the topology share
}

TEST(Report, NamesTheArmsAndTheLargestDisplacement) {
  ReportInputs in = inputs();
  in.analysis.control_arm = "feedforward";
  in.analysis.experimental_arm = "recurrent-sparse";
  RunAnalysis r;
  r.max_d = 7.25;
  in.analysis.experimental.push_back(r);
  in.target_distance = 50;
  in.outcome_pngs = {"outcomes-feedforward.png"};
  const std::string md = markdown_report(in);
  EXPECT_NE(md.find("| robozoo feed-forward | robozoo recurrent (sparse start) |"), std::string::npos) << md;
  EXPECT_NE(md.find("7.250 m (recurrent (sparse start))"), std::string::npos) << md;
  EXPECT_NE(md.find("of the 50.0 m from the start to the target: fitness did not come near its ceiling"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("![outcome shares](outcomes-feedforward.png)"), std::string::npos) << md;
}

TEST(Report, Formatting) {
  EXPECT_EQ(format_p(0.0004), "< 0.001");
  EXPECT_EQ(format_p(0.0234), "0.023");
  EXPECT_EQ(format_p(std::nan("")), "n/a");
  EXPECT_EQ(format_mean_se(describe({0.05, 0.06})), "0.0550 ± 0.0050");
  EXPECT_EQ(format_mean_se(describe({})), "n/a");
}

TEST(PaperClaims, EveryClaimNamesAStatisticTheAnalysisComputes) {
  // The champion-change figures of the paper's section 4 are among the claims.
  bool found = false;
  for (const auto& c : paper_claims()) found |= c.key == "topology_changed" && c.paper.find("96.99") != std::string::npos;
  EXPECT_TRUE(found);
}

}  // namespace
}  // namespace robozoo
