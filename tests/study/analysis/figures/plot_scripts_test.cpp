// The figures' gnuplot scripts, run through the real gnuplot (gnuplot-nox,
// installed by tools/setup.sh) into PNG files.
#include "study/analysis/figures/plot_scripts.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "study/analysis/figures/gnuplot_runner.hpp"
#include "tests/support/subprocess.hpp"

namespace robozoo {
namespace {

using namespace robozoo::testing;

std::vector<CurvePoint> curve() {
  std::vector<CurvePoint> c;
  for (int g = 0; g < 5; ++g) {
    const std::vector<double> a = {10.0 + g, 12.0 + g}, b = {11.0 + 2 * g, 13.0 + 2 * g, 12.0 + 2 * g};
    c.push_back({g, describe(a), describe(b), ttest_ind(b, a)});
  }
  return c;
}

bool is_png(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  char magic[8] = {};
  f.read(magic, 8);
  return f.gcount() == 8 && std::string(magic + 1, 3) == "PNG";
}

void write(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

TEST(PlotScripts, FitnessCurveHoldsItsDataAndRendersAPng) {
  const std::string s = fitness_curve_script(curve(), "fig1.png", "Figure 1");
  EXPECT_NE(s.find("set terminal pngcairo"), std::string::npos);
  EXPECT_NE(s.find("set output \"fig1.png\""), std::string::npos);
  EXPECT_NE(s.find("4 15 1 20 0.5773502692"),
            std::string::npos);  // generation 4: {14, 16} and {19, 21, 20}: means 15, 20; s.e. 1, 1/sqrt(3)
  // Generation 4's Student's t: 5 / sqrt(4/3 (1/2 + 1/3)) = 4.74 with df 3, p < 0.05: marked, generation 0
  // (t = 1 / sqrt(10/9) = 0.95) is not.
  EXPECT_LT(curve()[4].student.p, 0.05);
  EXPECT_GT(curve()[0].student.p, 0.05);
  EXPECT_NE(s.find("$curve using 1:($6 < 0.05 ? "), std::string::npos) << s;
  EXPECT_NE(s.find("title \"p < 0.05 (Student's t per generation, uncorrected)\""), std::string::npos) << s;
  std::vector<CurvePoint> untested = curve();
  for (auto& p : untested) p.student = TTestResult{};
  EXPECT_EQ(fitness_curve_script(untested, "fig1.png", "Figure 1").find("per generation"), std::string::npos);
  TempDir dir;
  write(dir / "fig1.gp", s);
  ASSERT_TRUE(gnuplot_available());
  run_gnuplot("fig1.gp", "gnuplot", dir.path);
  EXPECT_TRUE(is_png(dir / "fig1.png"));
}

TEST(PlotScripts, BarPanelsWithStarsAndEmptySamples) {
  std::vector<Comparison> list = {
      compare("joints", "joints", "count", {1, 2, 3, 2}, {6, 7, 8, 7}),
      compare("share", "a share", "share", {0.5, 0.25}, {1, 0.75}),
      compare("empty", "no data", "count", {}, {}),
  };
  const std::string s = comparison_panels_script(list, "bars.png", "Figure 2", 2);
  EXPECT_NE(s.find("set multiplot layout 2,2"), std::string::npos);
  EXPECT_NE(s.find("***"), std::string::npos);      // joints differ strongly
  EXPECT_NE(s.find("1 87.5 "), std::string::npos);  // the share in per cent
  TempDir dir;
  write(dir / "bars.gp", s);
  run_gnuplot("bars.gp", "gnuplot", dir.path);
  EXPECT_TRUE(is_png(dir / "bars.png"));
}

TEST(PlotScripts, GnuplotErrorsAreReported) {
  TempDir dir;
  write(dir / "bad.gp", "plot $nothing using 1:2\n");
  EXPECT_THROW(run_gnuplot("bad.gp", "gnuplot", dir.path), std::runtime_error);
  EXPECT_THROW(run_gnuplot("x.gp", "/nonexistent/gnuplot", dir.path), std::runtime_error);
  EXPECT_FALSE(gnuplot_available("/nonexistent/gnuplot"));
  EXPECT_THROW(fitness_curve_script({}, "x.png", "t"), std::invalid_argument);
}

TEST(PlotScripts, Quoting) { EXPECT_EQ(gnuplot_quote("a \"b\"\\\nc"), "\"a \\\"b\\\"\\\\\\nc\""); }

TEST(PlotScripts, EnhancedTextPrintsMarkupCharactersAsThemselves) {
  // In the file: "max\\_spheres" (the string max\_spheres, which enhanced text prints as max_spheres).
  EXPECT_EQ(gnuplot_text("max_spheres"), "\"max\\\\_spheres\"");
  EXPECT_EQ(gnuplot_text("a@b&c~d{e}"), "\"a\\\\@b\\\\&c\\\\~d\\\\{e\\\\}\"");
  EXPECT_EQ(gnuplot_text("m^2"), "\"m^2\"");
  // Every drawn text goes through it; file names do not.
  std::vector<Comparison> one(1);
  one[0].label = "robots at max_spheres";
  one[0].unit = "count";
  one[0].control.n = one[0].experimental.n = 1;
  const std::string s = comparison_panels_script(one, "out_dir/x_y.png", "fig_title", 1);
  EXPECT_NE(s.find("set output \"out_dir/x_y.png\""), std::string::npos);
  EXPECT_NE(s.find("title \"fig\\\\_title\""), std::string::npos);
  EXPECT_NE(s.find("robots at max\\\\_spheres"), std::string::npos);
  EXPECT_EQ(s.find("max_spheres"), std::string::npos);
}

TEST(PlotScripts, OutcomeSharesSpanExactlyTheGenerations) {
  const std::vector<std::array<double, 6>> shares(3, {0.5, 0.5, 0, 0, 0, 0});
  EXPECT_NE(outcome_shares_script(shares, "o.png", "t").find("set xrange [0:2]\n"), std::string::npos);
  EXPECT_EQ(outcome_shares_script({shares[0]}, "o.png", "t").find("set xrange"), std::string::npos);
}

}  // namespace
}  // namespace robozoo
