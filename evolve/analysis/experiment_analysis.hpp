#pragma once
// The comparison of the two regimes over the runs of an experiment: the
// paper's Figure 1 (mean best-so-far fitness per generation, +-1 standard
// error), Figure 2 (body plans of the best-of-run robots), Figure 3 (their
// CPPNs) and the champion-change analysis of section 4, each statistic with
// Student's two-sample t-test (ttest.hpp) between the regimes.
#include <cstdint>
#include <string>
#include <vector>

#include "evolve/analysis/run_analysis.hpp"
#include "evolve/analysis/sample_stats.hpp"
#include "evolve/analysis/ttest.hpp"

namespace robozoo {

/// One statistic compared between the control (feed-forward) and the
/// experimental (recurrent) regime.
struct Comparison {
  std::string key;        ///< short name (CSV column, plot file)
  std::string label;      ///< what it is, for people
  std::string unit;       ///< unit of the values
  SampleStats control;    ///< feed-forward sample
  SampleStats experimental;  ///< recurrent sample
  TTestResult test;       ///< control against experimental
  std::string stars;      ///< significance_stars(test.p)
};

/// Builds a comparison of two samples.
Comparison compare(const std::string& key, const std::string& label, const std::string& unit,
                   const std::vector<double>& control, const std::vector<double>& experimental);

struct CurvePoint {
  int32_t generation = 0;
  SampleStats control;       ///< best-so-far fitness over the feed-forward runs that reached this generation
  SampleStats experimental;  ///< the same over the recurrent runs
};

struct ExperimentAnalysis {
  std::string control_arm = "feedforward";   ///< the arm compared as the control
  std::string experimental_arm = "recurrent";///< the arm compared as the experimental regime
  std::vector<RunAnalysis> control;       ///< the control arm's runs, by seed
  std::vector<RunAnalysis> experimental;  ///< the experimental arm's runs, by seed
  std::vector<RunAnalysis> other;         ///< runs of other arms (not compared), by arm and seed
  std::vector<CurvePoint> fitness_curve;  ///< Figure 1
  std::vector<Comparison> fitness;        ///< best-of-run fitness
  std::vector<Comparison> morphology;     ///< Figure 2
  std::vector<Comparison> genotype;       ///< Figure 3
  std::vector<Comparison> champion;       ///< section 4
  /// Best-of-run robots without a pose stream (ground statistics counted as 0), per regime (count).
  int32_t control_without_poses = 0, experimental_without_poses = 0;
};

/// Compares two arms over `runs` (runs without a best-of-run robot count
/// in the fitness curve and fitness, not in the robot statistics); runs of
/// other arms are kept in `other`.
ExperimentAnalysis analyze_experiment(std::vector<RunAnalysis> runs, const std::string& control_arm = "feedforward",
                                      const std::string& experimental_arm = "recurrent");

/// An arm's name for people: "feed-forward", "recurrent", "recurrent (sparse start)".
std::string arm_title(const std::string& arm);
/// An arm's name as a CSV column prefix: "feedforward", "recurrent", "recurrent_sparse".
std::string arm_column(const std::string& arm);

/// The comparison with `key` in `list`, or nullptr.
const Comparison* find_comparison(const std::vector<Comparison>& list, const std::string& key);

}  // namespace robozoo
