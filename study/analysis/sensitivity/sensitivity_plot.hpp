#pragma once
// The sensitivity study's figure (sensitivity.png, from sensitivity.gp): one
// row per factor, top to bottom in the report's order; on it the factor's gap
// in best-so-far fitness (control mean minus experimental mean) at the compared
// generation with its interval, and just below it the reference's gap on the
// same seeds with its interval; a dashed line at 0 (no gap). The script holds
// its data (a gnuplot datablock), like the experiment's other figures.
#include <string>

#include "study/analysis/figures/plot_scripts.hpp"
#include "study/analysis/sensitivity/sensitivity_analysis.hpp"

namespace robozoo {

/// The gnuplot script that draws `a` into `png_path`. A gap without an
/// interval (an arm with fewer than two runs) is drawn without error bars;
/// one that is not a number is not drawn.
std::string sensitivity_plot_script(const SensitivityAnalysis& a, const std::string& png_path, const std::string& title,
                                    const PlotStyle& style = {});

}  // namespace robozoo
