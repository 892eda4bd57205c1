#include "study/analysis/sensitivity/sensitivity_report.hpp"

#include "study/analysis/sensitivity/sensitivity_plot.hpp"

#include <gtest/gtest.h>

#include <sstream>

namespace robozoo {
namespace {

SensitivityAnalysis two_factors() {
  SensitivityAnalysis a;
  a.params.generation = 30;
  a.software_version = "2f4ba41c77a6";
  FactorResult f;
  f.name = "bias-1.0";
  f.changes = {{"growth.bias_input", "0.3", "1.0"}};
  f.control_seeds = {1, 5};
  f.experimental_seeds = {2, 6};
  f.gap = student_gap({20, 24}, {10, 12});
  f.reference_gap = student_gap({12, 14}, {11, 12});
  f.difference = gap_difference(f.gap, f.reference_gap);
  f.holm_p = 0.25;
  f.reading = "inconclusive: the interval holds both 0 and the reference's gap";
  f.control_outcomes.runs = 2;
  f.control_outcomes.counts = {30, 200, 20, 10, 40, 0};
  a.factors.push_back(f);
  f.name = "cap-100";
  f.changes = {{"growth.max_spheres", "50", "100"}};
  a.factors.push_back(f);
  return a;
}

size_t lines(const std::string& s) {
  size_t n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

TEST(SensitivityReport, TheCsvFilesHoldARowPerFactorAndPerArm) {
  const SensitivityAnalysis a = two_factors();
  const std::string csv = sensitivity_csv(a);
  EXPECT_EQ(lines(csv), 3u);
  EXPECT_EQ(csv.rfind("factor,changes,generation,", 0), 0u);
  EXPECT_NE(csv.find("bias-1.0,growth.bias_input 0.3 -> 1.0,30,feedforward,recurrent,1 5,2 6,22,11,11,"),
            std::string::npos)
      << csv;
  const std::string outcomes = sensitivity_outcomes_csv(a);
  EXPECT_EQ(lines(outcomes), 1u + 2 * 4);
  EXPECT_NE(outcomes.find("bias-1.0,factor,feedforward,30,2,300,30,200,20,10,40,0"), std::string::npos) << outcomes;
  EXPECT_NE(outcomes.find("cap-100,reference,recurrent,30,0,0,0,0,0,0,0,0"), std::string::npos) << outcomes;
}

TEST(SensitivityReport, TheReportSaysWhatWasComparedAndHowToMakeItAgain) {
  SensitivityReportInputs in;
  in.title = "the study";
  in.factors_dir = "media/experiment/paper/sensitivity";
  in.reference_dir = "media/experiment/paper/m3/results";
  in.waiting = {"no-contact-rule"};
  in.notes = {"A note."};
  in.command = "build/bin/robozoo-stats a --sensitivity b --generation 30";
  in.analysis = two_factors();
  const std::string md = sensitivity_markdown(in);
  EXPECT_EQ(md.rfind("# the study\n\nA note.\n\n", 0), 0u) << md;
  EXPECT_NE(md.find("robozoo 2f4ba41c77a6"), std::string::npos);
  EXPECT_NE(md.find("after 30 generations (generation record 29, counted from 0)"), std::string::npos);
  EXPECT_NE(md.find("| bias-1.0 | `growth.bias_input` 0.3 → 1.0 | 22.00 (2) | 11.00 (2) | 11.00 ["), std::string::npos)
      << md;
  EXPECT_NE(md.find("| cap-100 | `growth.max_spheres` 50 → 100 |"), std::string::npos);
  EXPECT_NE(md.find("| 0.250 | "), std::string::npos);
  EXPECT_NE(md.find("inconclusive: the interval holds both 0 and the reference's gap |"), std::string::npos);
  EXPECT_NE(md.find("- bias-1.0: seeds feedforward 1 5; recurrent 2 6."), std::string::npos);
  EXPECT_NE(md.find("- Factors without results yet: no-contact-rule."), std::string::npos);
  // Outcome shares of 300 evaluations: simulated (200 + 20) 73.3 %, not simulated 10.0 %.
  EXPECT_NE(md.find("| bias-1.0 | the factor | feedforward | 2 | 300 | 73.3 % | 3.3 % | 13.3 % | 0.0 % | 10.0 % |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| cap-100 | the reference | recurrent | 0 | 0 | n/a |"), std::string::npos);
  EXPECT_NE(md.find("## Reproduce\n\n```sh\nbuild/bin/robozoo-stats a --sensitivity b --generation 30\n```\n"),
            std::string::npos);
}

TEST(SensitivityPlot, EachFactorsGapAndTheReferencesWithTheirIntervalsTopToBottom) {
  SensitivityAnalysis a = two_factors();
  a.factors[1].reference_gap = MeanGap{};  // a gap without an interval (as with one run per arm)
  a.factors[1].reference_gap.gap = 1.0;
  const std::string gp = sensitivity_plot_script(a, "sensitivity.png", "The gap");
  EXPECT_NE(gp.find("set output \"sensitivity.png\""), std::string::npos) << gp;
  // bias-1.0 first, on top (y = 2): gap 11 = 22 - 11 with Student's interval; its reference a quarter below.
  const MeanGap& g = a.factors[0].gap;
  char line[200];
  std::snprintf(line, sizeof line, "\n2 11 %.10g %.10g\n", g.low, g.high);
  EXPECT_NE(gp.find("$factor << EOD" + std::string(line)), std::string::npos) << gp;
  const MeanGap& r = a.factors[0].reference_gap;
  std::snprintf(line, sizeof line, "\n1.75 %.10g %.10g %.10g\n", r.gap, r.low, r.high);
  EXPECT_NE(gp.find("$reference << EOD" + std::string(line)), std::string::npos) << gp;
  // cap-100's reference has no interval: drawn at its gap without bars.
  EXPECT_NE(gp.find("\n0.75 1 1 1\nEOD"), std::string::npos) << gp;
  EXPECT_NE(gp.find("set ytics (\"bias-1.0\" 2, \"cap-100\" 1)"), std::string::npos) << gp;
  EXPECT_NE(gp.find("after 30 generations: feedforward mean minus recurrent mean, with its 95 % interval"),
            std::string::npos)
      << gp;
}

}  // namespace
}  // namespace robozoo
