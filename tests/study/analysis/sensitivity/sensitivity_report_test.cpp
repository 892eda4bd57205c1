#include "study/analysis/sensitivity/sensitivity_report.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "tests/study/analysis/sensitivity/two_factors.hpp"

namespace robozoo {
namespace {

using robozoo::testing::two_factors;

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
  EXPECT_NE(md.find("The factors' tests (gap = 0) are **secondary**: a family of their own under Holm's correction at "
                    "α = 0.05, apart from the reference's primary test"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| bias-1.0 | `growth.bias_input` 0.3 → 1.0 | 22.00 (2) | 11.00 (2) | 11.00 ["), std::string::npos)
      << md;
  EXPECT_NE(md.find("| cap-100 | `growth.max_spheres` 50 → 100 |"), std::string::npos);
  EXPECT_NE(md.find("| 0.250 | "), std::string::npos);
  EXPECT_NE(md.find("inconclusive: the interval holds both 0 and the reference's gap |"), std::string::npos);
  EXPECT_NE(md.find("- bias-1.0: seeds feedforward 1 5; recurrent 2 6."), std::string::npos);
  EXPECT_NE(md.find("- Factors without results yet: no-contact-rule."), std::string::npos);
  EXPECT_EQ(md.find("Fewer runs"), std::string::npos) << md;
  // Outcome shares of 300 evaluations: simulated (200 + 20) 73.3 %, not simulated 10.0 %.
  EXPECT_NE(md.find("| bias-1.0 | the factor | feedforward | 2 | 300 | 73.3 % | 3.3 % | 13.3 % | 0.0 % | 10.0 % |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| cap-100 | the reference | recurrent | 0 | 0 | n/a |"), std::string::npos);
  EXPECT_NE(md.find("## Reproduce\n\n```sh\nbuild/bin/robozoo-stats a --sensitivity b --generation 30\n```\n"),
            std::string::npos);
}

TEST(SensitivityReport, AFactorWithFewerRunsThanTheOthersIsMarked) {
  SensitivityReportInputs in;
  in.analysis = two_factors();
  in.analysis.factors[1].control_seeds = {1};
  const std::string md = sensitivity_markdown(in);
  EXPECT_NE(md.find("- **Fewer runs than the other factors** (still running, or trials missing; compared on the seeds "
                    "it has): cap-100 (1 feedforward and 2 recurrent runs, against 2 and 2).\n"),
            std::string::npos)
      << md;
}

}  // namespace
}  // namespace robozoo
