// The sensitivity study's figure: its script holds each factor's gap and the
// reference's, with their intervals, top to bottom in the report's order.
#include "study/analysis/sensitivity/sensitivity_plot.hpp"

#include <gtest/gtest.h>

#include <cstdio>

#include "tests/study/analysis/sensitivity/two_factors.hpp"

namespace robozoo {
namespace {

using robozoo::testing::two_factors;

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
