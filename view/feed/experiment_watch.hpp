#pragma once
// robozoo-view --experiment DIR: an experiment folder (robozoo-experiment's
// <arm>-s<seed>.lcmlog trial logs and their .checkpoint files) followed while
// its trials run. Each poll reads only the bytes appended to each log since
// the last one (runlog's scan_event_log_from) and takes its ROBOZOO_RUN and
// ROBOZOO_GENERATION messages; the rest of the log is not decoded.
//
// Trials finished elsewhere (another machine, a committed milestone) are known
// only from their compact results (<arm>-s<seed>.results.json, study's
// run_results): the folders in `results_dirs` are polled too, and a trial
// found there without a log in DIR is shown from its result, finished (a file
// is read again only when its size or time changes; one that does not read is
// listed, not shown). A trial with a log is shown from its log. Portable
// checkpoints there (<arm>-s<seed>.portable-checkpoint, a trial in progress
// elsewhere) count as the compact result of their finished generations.
//
// A log that begins at generation k (a trial continued here from a portable
// checkpoint) takes generations 0..k-1 from the earlier result beside it
// (<log>.earlier.json). A log cut back under what was read (a stopped trial
// resumed: robozoo-evolve cuts the unfinished generation) or rewritten is read
// again from its start; one that cannot be read keeps what was shown, marked
// stopped, and is listed as unreadable. A generation number beyond the run's
// planned generations (or kMaxWatchedGenerations) is damage, not a size.
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

/// The most generations a trial may show (a larger generation number is damage).
inline constexpr int32_t kMaxWatchedGenerations = 1000000;

struct ExperimentWatchOptions {
  double running_seconds = 60.0;  ///< a trial whose log or checkpoint changed this recently is running (s)
  double alpha = 0.05;            ///< significance level of the per-generation t-tests
  /// Folders of compact results (*.results.json) whose trials count too where DIR has no log of them.
  std::vector<std::string> results_dirs;
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
  std::string tail;                 ///< the log's last bytes before `offset` (up to 256): a rewrite changes them
  std::string results_path;         ///< its compact result, when it is known from one alone (no log)
  std::string results_stamp;        ///< size and time of that file when it was read
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
  /// The compact result of the trial called `name` when it is known from that alone, else "".
  std::string results_of(const std::string& name) const;

 private:
  void read_trial(TrialProgress& t);
  /// Trials of the results folders without a log here; true when anything changed.
  bool poll_results();
  nlohmann::json summary_json_locked() const;

  std::string dir_;
  ExperimentWatchOptions options_;
  mutable std::mutex mutex_;
  std::map<std::string, TrialProgress> trials_;    ///< by name
  std::map<std::string, std::string> unreadable_;  ///< result file -> why it was not shown
  std::string summary_;
};

}  // namespace robozoo::view
