#pragma once
// What `robozoo-stats DIR --sensitivity REFERENCE` does: reads each factor's
// compact results (DIR/<factor>/results/*.results.json; a factor folder without
// any yet is listed as waiting) and the reference's (REFERENCE/*.results.json),
// analyses them (sensitivity_analysis) and writes sensitivity.csv,
// sensitivity_outcomes.csv, report.md (sensitivity_report) and the figure,
// sensitivity.gp and the sensitivity.png gnuplot draws from it (sensitivity_plot),
// into the output folder.
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "study/analysis/sensitivity/sensitivity_analysis.hpp"

namespace robozoo {

struct SensitivityOptions {
  std::string factors_dir;    ///< one folder per factor, each with results/
  std::string reference_dir;  ///< the reference's compact results
  std::string out_dir;        ///< where the files go (empty: factors_dir)
  int32_t generation = 0;     ///< generations compared (count; 0: the factors' runs' length, all equal)
  double alpha = 0.05;        ///< significance level of Holm's family
  std::string control_arm = "feedforward";
  std::string experimental_arm = "recurrent";
  std::string title = "robozoo: the sensitivity study";
  std::vector<std::string> notes;   ///< paragraphs for the top of the report
  bool plots = true;                ///< run gnuplot for the figure
  std::string gnuplot = "gnuplot";  ///< the gnuplot program
};

struct SensitivityOutcome {
  SensitivityAnalysis analysis;
  std::vector<std::string> waiting;  ///< factor folders without results yet
  std::vector<std::string> files;    ///< written, in the output folder
  std::string out_dir;
};

/// Throws std::invalid_argument for a missing folder, no factor with results, runs of
/// different lengths without a generation asked for, or any run the analysis refuses;
/// std::runtime_error when a file cannot be written or gnuplot cannot run (with `plots`).
SensitivityOutcome run_sensitivity(const SensitivityOptions& options, std::ostream& progress);

}  // namespace robozoo
