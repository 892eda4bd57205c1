#pragma once
// The experiment's Markdown report: each of the paper's claims beside the
// figure robozoo measured, the plots, the zoo sheets and what the data were.
#include <string>
#include <vector>

#include "study/analysis/compare/experiment_analysis.hpp"

namespace robozoo {

struct ZooSheet {
  std::string regime;  ///< "feed-forward" / "recurrent"
  std::string file;    ///< image next to the report, empty when it could not be made
  std::string note;    ///< why it is missing, or how it was made
};

struct ReportInputs {
  std::string title = "robozoo: recurrent vs feed-forward CPPNs";
  std::string source;                 ///< where the logs came from (folder)
  std::vector<std::string> preamble;  ///< paragraphs before the tables (sizes, how long it took)
  ExperimentAnalysis analysis;
  std::string fitness_png;                ///< Figure 1 file name, relative to the report ("" if none)
  std::string morphology_png;             ///< Figure 2
  std::string genotype_png;               ///< Figure 3
  std::string champion_png;               ///< champion-change figure
  std::vector<std::string> outcome_pngs;  ///< outcome shares per generation, one plot per arm
  double target_distance = 0;             ///< distance from the origin to the target (m; 0: unknown)
  std::vector<ZooSheet> zoo;              ///< Figure 4
  std::vector<std::string> notes;         ///< skipped logs, decisions, anything a reader must know
  std::vector<std::string> commands;      ///< how to reproduce (shell lines)
  double alpha = 0.05;                    ///< significance level of every test
};

/// The report as Markdown.
std::string markdown_report(const ReportInputs& in);

/// "m +- se" with a precision that suits the value, e.g. "12.3 ± 0.4".
std::string format_mean_se(const SampleStats& s, double scale = 1.0);
/// A number for people at the report's precision: one decimal from 100, two from 1, more below
/// ("127.5", "27.54", "0.0125"; "n/a" for NaN).
std::string format_number(double v);
/// A p-value for people: "< 0.001", "0.023", "n/a".
std::string format_p(double p);

}  // namespace robozoo
