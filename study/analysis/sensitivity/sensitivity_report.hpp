#pragma once
// The sensitivity study's tables and Markdown report (sensitivity_analysis):
//   sensitivity.csv           one row per factor: the change, the runs, both arms'
//                             means, the gap with its interval, Student's and Holm's p,
//                             the reference's gap on the same seeds, their difference,
//                             the reading;
//   sensitivity_outcomes.csv  one row per factor and arm (and the reference on the
//                             factor's seeds): the generation's evaluations by outcome;
//   report.md                 both as tables (and the figure, sensitivity_plot), with what was compared and how, the
//                             factors still without results, and the command that
//                             makes the files again.
#include <string>
#include <vector>

#include "study/analysis/sensitivity/sensitivity_analysis.hpp"

namespace robozoo {

struct SensitivityReportInputs {
  std::string title;                 ///< the report's heading
  std::string factors_dir;           ///< the folder of factors read (as given)
  std::string reference_dir;         ///< the reference's compact results (as given)
  std::vector<std::string> waiting;  ///< factors in factors_dir without results yet
  std::vector<std::string> notes;    ///< paragraphs for the top of the report
  std::string command;               ///< the command that makes the files again
  std::string figure;                ///< the figure's PNG in the report's folder (empty: none)
  SensitivityAnalysis analysis;
};

std::string sensitivity_csv(const SensitivityAnalysis& a);
std::string sensitivity_outcomes_csv(const SensitivityAnalysis& a);
std::string sensitivity_markdown(const SensitivityReportInputs& in);

}  // namespace robozoo
