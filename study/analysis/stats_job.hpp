#pragma once
// What robozoo-stats does with a folder of logs: reads every run (one at a
// time), compares the regimes, and writes the CSV tables, the gnuplot scripts
// and PNG plots, the zoo sheets (with robozoo-render, when it is there) and the
// Markdown report into the output folder.
#include <ostream>
#include <string>
#include <vector>

#include "study/analysis/compare/experiment_analysis.hpp"
#include "study/analysis/measure/run_analysis.hpp"
#include "evolve/record/run_results.hpp"

namespace robozoo {

struct StatsOptions {
  std::string log_dir;  ///< folder of the runs' logs (*.lcmlog), or else of their compact results (*.results.json)
  std::string out_dir;  ///< where the tables, plots and report go (empty: <log_dir>/stats)
  bool include_unfinished = false;  ///< also use runs whose log lacks generations (default: skip them)
  AnalysisParams analysis;          ///< ground tolerance, topology, which champion changes count
  bool plots = true;                ///< run gnuplot
  std::string gnuplot = "gnuplot";  ///< the gnuplot program
  bool zoo = true;                  ///< make zoo sheets with robozoo-render
  std::string render;               ///< the robozoo-render program (empty: next to the running program)
  std::string title = "robozoo: recurrent vs feed-forward CPPNs";
  std::string control_arm = "feedforward";     ///< the arm compared as the control
  std::string experimental_arm = "recurrent";  ///< the arm compared as the experimental regime
  std::vector<std::string> notes;              ///< paragraphs for the top of the report
  double alpha = 0.05;                         ///< significance level of every test (the paper's)
};

struct StatsOutcome {
  ExperimentAnalysis analysis;
  std::vector<std::string> skipped;  ///< logs left out, with why
  std::vector<std::string> files;    ///< files written, in the output folder
  std::string out_dir;
};

/// Name order with runs of digits compared as numbers ("s2" < "s10").
bool natural_less(const std::string& a, const std::string& b);

/// The logs (*.lcmlog) directly in `dir`, sorted by name with runs of digits
/// compared as numbers (recurrent-s2 before recurrent-s10, so zoo sheets show
/// the seeds in order). Throws std::invalid_argument when `dir` is not a folder.
std::vector<std::string> list_logs(const std::string& dir);

/// The compact results (*.results.json) directly in `dir`, in list_logs' order.
std::vector<std::string> list_results(const std::string& dir);

/// "<log name without .lcmlog>.results.json".
std::string results_file_name(const std::string& log_path);

/// Writes the compact results of every log in `log_dir` into `out_dir`
/// (created if missing), one file per log; logs that cannot be read, and
/// unfinished ones unless `include_unfinished`, are listed in `skipped`.
/// Returns the files written. Throws std::invalid_argument when there is no log.
std::vector<std::string> export_results(const std::string& log_dir, const std::string& out_dir, bool include_unfinished,
                                        std::ostream& progress, std::vector<std::string>& skipped);

/// Runs the whole job, telling `progress` what it does; reads the logs of
/// `log_dir`, or its compact results when it holds no log (the same report,
/// except the zoo sheets, which need logs). Throws
/// std::invalid_argument when there is no usable log, std::runtime_error when an
/// output cannot be written or gnuplot fails.
StatsOutcome run_stats(const StatsOptions& options, std::ostream& progress);

}  // namespace robozoo
