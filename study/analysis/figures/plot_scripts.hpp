#pragma once
// gnuplot scripts for the experiment's figures. Each script holds its data
// (gnuplot datablocks), so it can be re-run or edited by hand next to its PNG.
// Colours follow the paper: control (feed-forward) blue lines / white bars,
// experimental (recurrent) red.
#include <array>
#include <string>
#include <vector>

#include "study/analysis/compare/experiment_analysis.hpp"

namespace robozoo {

struct PlotStyle {
  int width = 1200;                              ///< image width (pixels)
  int height = 800;                              ///< image height (pixels)
  std::string font = "DejaVu Sans,11";           ///< pngcairo font
  std::string control_label = "feed-forward";    ///< the control arm, for keys and axes
  std::string experimental_label = "recurrent";  ///< the experimental arm
};

/// Figure 1: mean best-so-far fitness per generation of each regime, with +-1
/// standard error as dotted lines around a shaded band; the generations whose
/// Student's t-test gives p < alpha are marked by dots below the curves.
std::string fitness_curve_script(const std::vector<CurvePoint>& curve, const std::string& png_path,
                                 const std::string& title, const PlotStyle& style = {}, double alpha = 0.05);

/// One bar panel per comparison (mean +- 1 standard error of each regime),
/// the paper's asterisks in the panel's title; `scale` multiplies the values of
/// comparisons whose unit is "share" (100 shows them in per cent).
std::string comparison_panels_script(const std::vector<Comparison>& comparisons, const std::string& png_path,
                                     const std::string& title, int columns, const PlotStyle& style = {},
                                     double share_scale = 100.0);

/// The share of each outcome per generation, averaged over an arm's runs
/// (`shares[g][k]`: generation g, outcome k in generation_t's order), as
/// stacked areas.
std::string outcome_shares_script(const std::vector<std::array<double, 6>>& shares, const std::string& png_path,
                                  const std::string& title, const PlotStyle& style = {});

/// A number as a gnuplot datablock writes it (NaN, which gnuplot skips, when not finite).
std::string gnuplot_number(double v);

/// The lines that open every script: the pngcairo terminal of `style` writing `png_path`.
std::string gnuplot_png_terminal(const std::string& png_path, const PlotStyle& style);

/// Escapes a string for a double-quoted gnuplot string literal.
std::string gnuplot_quote(const std::string& s);

/// A double-quoted gnuplot string literal for text drawn by the "enhanced"
/// terminal (titles, keys, tick labels): `_ @ & ~ { }` print as themselves
/// (enhanced text would take `max_spheres` for max with a subscript s);
/// `^` stays a superscript, for units such as m^2.
std::string gnuplot_text(const std::string& s);

}  // namespace robozoo
