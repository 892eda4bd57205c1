#pragma once
// The state of a run between two generations, written atomically (write a
// temporary file, fsync, rename) after every generation, so that a run killed at
// any moment resumes exactly (docs/method.md section 4).
#include <cstdint>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "evolve/messages/log_continuation.hpp"
#include "evolve/neat/population.hpp"

namespace robozoo {

struct Checkpoint {
  /// 2: node genes carry drawing positions, the population its speciation
  /// threshold (HyperNEAT's topology rules). Version 1 is refused.
  static constexpr int kFormatVersion = 2;
  std::string run_id;
  std::string software_version;
  nlohmann::json config;            ///< the resolved configuration (config_to_json)
  PopulationState population;       ///< the next generation to evaluate
  std::string rng_state;            ///< Rng::state() after breeding it
  int64_t evaluations = 0;          ///< cumulative evaluations so far (count)
  double best_so_far = 0.0;         ///< best fitness since generation 0
  uint64_t last_champion_hash = 0;  ///< content hash (id aside) of the last generation's champion
  int64_t log_bytes = 0;            ///< size of the log after the last finished generation
  int64_t log_events = 0;           ///< events in the log after the last finished generation
  double elapsed_seconds = 0.0;     ///< wall time spent so far (s)
  bool finished = false;            ///< every generation done
  /// Set when the run's log begins at a later generation than 0 (a run continued
  /// from a portable checkpoint on a machine without its log): every run message
  /// of the log says so (log_continuation.hpp). Written as "log_continues" only
  /// when set, so a checkpoint of a log that starts at generation 0 is as before.
  std::optional<LogContinuation> log_continues;
};

/// Where the checkpoint of the run logged at `log_path` lives: beside it, `log_path` + ".checkpoint".
std::string checkpoint_path_for(const std::string& log_path);

/// The checkpoint's text, as write_checkpoint writes it.
std::string checkpoint_to_text(const Checkpoint& c);
/// Writes atomically: `path` holds either the old or the new checkpoint, never a mix.
void write_checkpoint(const std::string& path, const Checkpoint& c);
/// Throws std::runtime_error naming the path for a missing, unreadable or malformed file.
Checkpoint read_checkpoint(const std::string& path);
/// The same on a checkpoint's text; `path` names it in error messages.
Checkpoint checkpoint_from_text(const std::string& text, const std::string& path);

/// Writes `text` to `path` atomically (temporary file in the same folder, fsync, rename, fsync folder).
void write_file_atomic(const std::string& path, const std::string& text);

}  // namespace robozoo
