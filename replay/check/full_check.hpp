#pragma once
// `robozoo-replay check --full`: the whole evolution re-run from the log's
// ROBOZOO_RUN (its seed and configuration), and every message it writes compared
// with the log's, in order. It costs one evolution.
//
// Left out of the comparison (the volatile fields, nothing else):
//   - utime of every message (publication time);
//   - generation_t.eval_seconds and generation_t.generation_seconds (timings);
//   - run_t.software_version, only with --force (a log of another version).
// Everything else must be equal bit for bit (the messages are compared as
// normalised bytes, see evolve/io/log_compare.hpp).
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "evolve/config/run_config.hpp"
#include "evolve/run/evaluator.hpp"
#include "evolve/run/evolution.hpp"

namespace robozoo::replay {

struct FullCheckOptions {
  bool force = false;        ///< re-run a log written by another software version
  std::string work_dir;      ///< where the re-run's log and checkpoint go (must exist); empty: a temporary folder
  int max_generations = -1;  ///< -1: every generation the log holds; else at most this many (count)
};

/// The first message in which the re-run and the log differ.
struct FullDifference {
  int64_t index = -1;            ///< index among the run's robozoo events (0-based)
  int64_t logged_eventnum = -1;  ///< the log's event number, -1 if the log has no such event
  int64_t rerun_eventnum = -1;   ///< the re-run's event number, -1 if it wrote none
  std::string channel;           ///< the log's channel (or the re-run's when the log has none)
  std::string rerun_channel;
  int32_t generation = -1;       ///< the generation being compared
  std::string field;             ///< the first differing field, e.g. "links[3].weight"
  std::string logged, rerun;     ///< its values
  std::string describe() const;  ///< one sentence with all of the above
};

struct FullCheckReport {
  std::string log_path;
  std::string run_id;
  std::string software_version;  ///< of the log
  int64_t seed = 0;
  std::string regime;
  int32_t generations_logged = 0;  ///< ROBOZOO_GENERATION messages of the run in the log (count)
  int32_t generations_rerun = 0;   ///< generations evolved again (count)
  int64_t events_compared = 0;     ///< robozoo events found equal (count)
  bool diverged = false;
  FullDifference difference;                ///< when diverged
  std::vector<std::string> input_problems;  ///< damage of the log (it is still compared as read)
  std::string fatal;                        ///< not empty: nothing could be compared
  double seconds = 0.0;                     ///< wall time (s)
  /// 0 every message equal and the log intact; 1 a divergence; 2 unusable input.
  int exit_code() const;
};

/// Called after each re-run generation with (generations done, generations to do, elapsed s).
using FullCheckProgress = std::function<void(int done, int total, double elapsed_seconds)>;
/// Gives the evaluator for the re-run once the log's configuration is known (a
/// PoolEvaluator with N workers, or one over MPI ranks); the caller owns it.
using EvaluatorFactory = std::function<Evaluator&(const RunConfig& config)>;

/// Re-runs the log's run and compares. Bad input becomes a fatal report, never an
/// exception; an evaluator failure is fatal too.
FullCheckReport full_check(const std::string& log_path, const EvaluatorFactory& make_evaluator,
                           const FullCheckOptions& options, const FullCheckProgress& progress = {});

/// The report as text (a header, the verdict with the first difference, a summary).
std::string format_full_text(const FullCheckReport& r);
/// The same, machine-readable.
nlohmann::json to_json(const FullCheckReport& r);

}  // namespace robozoo::replay
