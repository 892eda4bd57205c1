#pragma once
// The experiment's CSV tables, built from its analysis.
#include <array>
#include "evolve/analysis/csv_writer.hpp"
#include "evolve/analysis/experiment_analysis.hpp"

namespace robozoo {

/// generation, n, mean and standard error of the best-so-far fitness of each regime (Figure 1).
CsvWriter fitness_curve_table(const ExperimentAnalysis& a);
/// One row per comparison: both samples (n, mean, sd, se), t, df, p, stars.
/// Columns named after the arms (`control` and `experimental` as arm_column prefixes).
CsvWriter comparison_table(const std::vector<Comparison>& list, const std::string& control = "feedforward",
                           const std::string& experimental = "recurrent");
/// Per generation, the mean share of each outcome over the runs of each arm
/// (the runs that reached that generation): arm, generation, runs, then one
/// column per outcome (generation_t's order).
CsvWriter outcome_shares_table(const ExperimentAnalysis& a);
/// Per generation, the mean share of each outcome over `runs`.
std::vector<std::array<double, 6>> mean_outcome_shares(const std::vector<RunAnalysis>& runs);
/// One row per run: identity, sizes, best-of-run fitness, morphology and genotype statistics, champion changes.
CsvWriter runs_table(const ExperimentAnalysis& a);
/// One row per new champion of every run (section 4's raw data).
CsvWriter champion_change_table(const ExperimentAnalysis& a);

}  // namespace robozoo
