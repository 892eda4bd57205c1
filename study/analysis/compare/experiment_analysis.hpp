#pragma once
// The comparison of the two regimes over the runs of an experiment: the
// paper's Figure 1 (mean best-so-far fitness per generation, +-1 standard
// error), Figure 2 (body plans of the best-of-run robots), Figure 3 (their
// CPPNs) and the champion-change analysis of section 4. Each statistic whose
// samples are runs gets Student's and Welch's t-test (ttest.hpp) and Cohen's d
// with its confidence interval (effect_size.hpp), all of the experimental arm
// against the control: positive when the experimental arm is higher.
#include <cstdint>
#include <string>
#include <vector>

#include "study/analysis/compare/effect_size.hpp"
#include "study/analysis/measure/run_analysis.hpp"
#include "study/analysis/compare/sample_stats.hpp"
#include "study/analysis/compare/ttest.hpp"

namespace robozoo {

/// What the samples of a comparison are.
enum class Samples {
  Runs,          ///< one value per run: independent samples, tested
  PooledEvents,  ///< every new champion of every run: not independent, described only (no test)
};

/// One statistic compared between the control and the experimental arm.
struct Comparison {
  std::string key;           ///< short name (CSV column, plot file)
  std::string label;         ///< what it is, for people
  std::string unit;          ///< unit of the values
  SampleStats control;       ///< control sample
  SampleStats experimental;  ///< experimental sample
  Samples samples = Samples::Runs;
  TTestResult student;  ///< Student's t, experimental against control (NaN for pooled events)
  TTestResult welch;    ///< Welch's t, experimental against control (NaN for pooled events)
  EffectSize effect;    ///< Cohen's d, experimental against control (NaN for pooled events)
  std::string stars;    ///< significance_stars(student.p)
  /// Best-of-run robots of each arm that reached growth.max_spheres, when the
  /// statistic is censored by that cap (count; -1: not censored by it).
  int32_t control_at_cap = -1, experimental_at_cap = -1;
};

/// Builds a comparison of two samples (tests only for Samples::Runs).
Comparison compare(const std::string& key, const std::string& label, const std::string& unit,
                   const std::vector<double>& control, const std::vector<double>& experimental,
                   Samples samples = Samples::Runs);

struct CurvePoint {
  int32_t generation = 0;
  SampleStats control;       ///< best-so-far fitness over the control runs that reached this generation
  SampleStats experimental;  ///< the same over the experimental runs
  TTestResult student;       ///< Student's t of this generation, experimental against control (descriptive)
};

/// The best-of-run fitness of a run of another arm against the control.
struct ArmFitness {
  std::string arm;     ///< the other arm
  Comparison fitness;  ///< its best-so-far fitness at the last generation against the control's
};

struct ExperimentAnalysis {
  std::string control_arm = "feedforward";     ///< the arm compared as the control
  std::string experimental_arm = "recurrent";  ///< the arm compared as the experimental regime
  std::vector<RunAnalysis> control;            ///< the control arm's runs, by seed
  std::vector<RunAnalysis> experimental;       ///< the experimental arm's runs, by seed
  std::vector<RunAnalysis> other;              ///< runs of other arms (not compared), by arm and seed
  std::vector<CurvePoint> fitness_curve;       ///< Figure 1
  std::vector<Comparison> fitness;             ///< best-of-run fitness
  std::vector<ArmFitness> other_arms;          ///< each arm of `other` against the control, by arm name
  std::vector<Comparison> morphology;          ///< Figure 2
  std::vector<Comparison> genotype;            ///< Figure 3
  std::vector<Comparison> champion;            ///< section 4
  /// Best-of-run robots without a pose stream (ground statistics counted as 0), per regime (count).
  int32_t control_without_poses = 0, experimental_without_poses = 0;
  /// Best-of-run robots with as many spheres as growth.max_spheres allows, per arm (count).
  int32_t control_at_cap = 0, experimental_at_cap = 0;
  /// The generation of the primary test: the last logged generation of the
  /// compared runs (0-based; -1 without any).
  int32_t last_generation = -1;
};

/// Compares two arms over `runs` (runs without a best-of-run robot count
/// in the fitness curve and fitness, not in the robot statistics); runs of
/// other arms are kept in `other`.
ExperimentAnalysis analyze_experiment(std::vector<RunAnalysis> runs, const std::string& control_arm = "feedforward",
                                      const std::string& experimental_arm = "recurrent");

/// An arm's name for people: "feed-forward", "recurrent", "recurrent (sparse start)",
/// "recurrent (zero-weight start)".
std::string arm_title(const std::string& arm);
/// An arm's name as a CSV column prefix: "feedforward", "recurrent", "recurrent_sparse".
std::string arm_column(const std::string& arm);
/// Statistics whose value is bounded by the number of spheres (censored when a
/// robot hit growth.max_spheres): spheres, leaves, joints, sensor counts, depth,
/// spheres on the ground.
bool censored_by_sphere_cap(const std::string& key);

/// The comparison with `key` in `list`, or nullptr.
const Comparison* find_comparison(const std::vector<Comparison>& list, const std::string& key);

}  // namespace robozoo
