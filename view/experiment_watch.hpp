#pragma once
// robozoo-view --experiment DIR: an experiment folder (robozoo-experiment's
// <arm>-s<seed>.lcmlog trial logs and their .checkpoint files) followed while
// its trials run. Each poll reads only the bytes appended to each log since
// the last one (runlog's scan_event_log_from) and takes its ROBOZOO_RUN and
// ROBOZOO_GENERATION messages; the rest of the log is not decoded.
//
// What the page gets (summary_json): every trial's best-so-far fitness per
// generation and its state; each arm's mean best-so-far per generation with
// its standard error (sample s.d. / sqrt(n), over the trials that reached that
// generation); and, for every pair of arms, Student's two-sided t-test per
// generation (study/analysis/compare/ttest: what robozoo-stats uses), p < alpha marked.
#include <cstdint>
#include <filesystem>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace robozoo::view {

struct ExperimentWatchOptions {
  double running_seconds = 60.0;  ///< a trial whose log or checkpoint changed this recently is running (s)
  double alpha = 0.05;            ///< significance level of the per-generation t-tests
};

/// One trial as read so far.
struct TrialProgress {
  std::string name;  ///< "<arm>-s<seed>", the log's name without .lcmlog
  std::string arm;
  int64_t seed = 0;
  std::string log_path;
  int32_t planned = 0;              ///< generations the run was started for (its ROBOZOO_RUN; 0 until seen)
  std::vector<double> best_so_far;  ///< per generation 0, 1, ... (fitness, m)
  std::string state;                ///< "running", "finished" or "stopped"
  bool checkpoint = false;          ///< <log>.checkpoint exists (a stopped trial can be resumed)
  int64_t offset = 0;               ///< bytes of the log read (up to the end of its last complete event)
};

/// An arm's curve: per generation, over the trials that reached it.
struct ArmCurve {
  std::string arm;
  std::vector<double> mean;  ///< mean best-so-far (fitness)
  std::vector<double> se;    ///< standard error of that mean (NaN with one trial)
  std::vector<int> n;        ///< trials (count)
};

/// The arms' curves, arms in name order.
std::vector<ArmCurve> arm_curves(const std::vector<TrialProgress>& trials);

/// Student's two-sided t-test p-value per generation between two arms' trials
/// (NaN where either has fewer than two trials at that generation).
std::vector<double> generation_p_values(const std::vector<TrialProgress>& trials, const std::string& a,
                                        const std::string& b);

class ExperimentWatch {
 public:
  /// Throws std::runtime_error with one line when `dir` is not a folder or
  /// holds no trial log (<arm>-s<seed>.lcmlog of a known arm).
  explicit ExperimentWatch(std::string dir, ExperimentWatchOptions options = {});

  /// Looks for new logs and reads what was appended to each; returns true
  /// when anything changed (a generation, a state, a new trial).
  bool poll();
  /// Everything the page shows, as JSON text (thread-safe: the server asks).
  std::string summary() const;
  std::vector<TrialProgress> trials() const;
  /// The log of the trial called `name`, or "" when there is none.
  std::string log_of(const std::string& name) const;

 private:
  void read_trial(TrialProgress& t);
  nlohmann::json summary_json_locked() const;

  std::string dir_;
  ExperimentWatchOptions options_;
  mutable std::mutex mutex_;
  std::map<std::string, TrialProgress> trials_;  ///< by name
  std::string summary_;
};

}  // namespace robozoo::view
