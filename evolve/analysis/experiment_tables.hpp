#pragma once
// The experiment's CSV tables, built from its analysis.
#include "evolve/analysis/csv_writer.hpp"
#include "evolve/analysis/experiment_analysis.hpp"

namespace robozoo {

/// generation, n, mean and standard error of the best-so-far fitness of each regime (Figure 1).
CsvWriter fitness_curve_table(const ExperimentAnalysis& a);
/// One row per comparison: both samples (n, mean, sd, se), t, df, p, stars.
CsvWriter comparison_table(const std::vector<Comparison>& list);
/// One row per run: identity, sizes, best-of-run fitness, morphology and genotype statistics, champion changes.
CsvWriter runs_table(const ExperimentAnalysis& a);
/// One row per new champion of every run (section 4's raw data).
CsvWriter champion_change_table(const ExperimentAnalysis& a);

}  // namespace robozoo
