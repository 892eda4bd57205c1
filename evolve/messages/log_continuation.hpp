#pragma once
// A log that continues a run from a checkpoint made on another machine: it
// begins at the checkpoint's generation k, not at 0 (the generations before
// are in the run's earlier compact result, not in this log). Its run messages
// say so: run_t.config_json holds, besides the resolved configuration, the
// top-level key "log_continues" = {"from_generation": k, "evaluations_before":
// E, "best_so_far_before": b, "last_champion_key": h} (the run's state after
// generation k - 1). The key
// is no configuration parameter: every reader of run_t (the run summary of the
// statistics, robozoo-replay, re-grown trajectories) takes it out first, so the
// configuration it reads and compares is exactly the uninterrupted run's. A
// robozoo older than this key refuses such a log's configuration (an unknown
// key) rather than mistake it for a run that starts at generation 0.
#include <cstdint>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "robozoo/run_t.hpp"

namespace robozoo {

struct LogContinuation {
  int32_t from_generation = 0;     ///< the log's first generation, k >= 1 (count)
  int64_t evaluations_before = 0;  ///< cumulative evaluations after generation k - 1 (count)
  double best_so_far_before = 0;   ///< best fitness of generations 0..k-1 (fitness units)
  uint64_t last_champion_key = 0;  ///< content hash (id aside) of generation k - 1's champion: a champion
                                   ///< with its genes logs no trajectory of its own
  bool operator==(const LogContinuation& o) const;
};

/// The key of run_t.config_json that holds it.
inline constexpr const char* kLogContinuesKey = "log_continues";

nlohmann::json log_continuation_to_json(const LogContinuation& c);
/// Throws std::invalid_argument naming `path` and the field for a bad value.
LogContinuation log_continuation_from_json(const nlohmann::json& j, const std::string& path);

/// `m` with the continuation written into its config_json.
run_t mark_continued(run_t m, const LogContinuation& c);

/// A run message's configuration text without the continuation, and the continuation.
struct SplitRunConfig {
  std::string config_json;                   ///< the configuration text as an uninterrupted run logs it
  std::optional<LogContinuation> continues;  ///< empty: the log starts at generation 0
};
/// Takes the continuation out of `config_json`; text that is no JSON object, or
/// has no such key, is returned as it is. Throws std::invalid_argument for a
/// continuation that is malformed.
SplitRunConfig split_run_config(const std::string& config_json);

}  // namespace robozoo
