#pragma once
// What the experiment's statistics need from one run's log: the run's
// identity, every generation's fitness summary, every generation's champion
// (genome and morphology) and the lowest height each sphere reached in each
// logged pose stream. Read with safe_decode: a log is never trusted; a message
// that does not decode is counted and skipped. A log file is read with
// runlog/, the one reader of logs (summarize_run_file in
// study/analysis/read/log_results.hpp); a compact result (run_results.hpp)
// holds the same summary, reduced.
#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "evolve/io/event_log.hpp"
#include "evolve/messages/log_continuation.hpp"
#include "robozoo/cppn_genome_t.hpp"
#include "robozoo/morphology_t.hpp"

namespace robozoo {

struct GenerationRecord {
  int32_t generation = 0;              ///< 0-based
  double best_fitness = 0;             ///< fitness units
  double mean_fitness = 0;             ///< fitness units
  double best_so_far_fitness = 0;      ///< fitness units
  double stderr_fitness = 0;           ///< standard error of the mean fitness (fitness units)
  int64_t evaluations = 0;             ///< cumulative evaluations since the start of the run (count)
  int64_t champion_id = -1;            ///< genome id of the generation's champion
  int32_t num_species = 0;             ///< species after speciation (count)
  double compatibility_threshold = 0;  ///< NEAT compatibility threshold in force (distance units)
  /// Outcome counts of the generation (generation_t), in the outcome order:
  /// not simulated, completed, stopped early, acceleration fault, rolling by
  /// contact, rolling by spin (count).
  std::array<int32_t, 6> outcomes{};
};

struct ChampionRecord {
  int32_t generation = 0;       ///< generation the champion won
  cppn_genome_t genome;         ///< its logged genome (fitness, outcome, nodes, links)
  bool has_morphology = false;  ///< its morphology was logged and decoded
  morphology_t morphology;      ///< valid when has_morphology
};

struct RunSummary {
  std::string path;  ///< the log read
  std::string run_id;
  std::string software_version;
  int64_t seed = 0;
  int8_t regime = 0;                  ///< 0 feed-forward, 1 recurrent (run_t)
  std::string arm = "feedforward";    ///< the experiment arm of its configuration (arm_of)
  int32_t max_spheres = 0;            ///< growth.max_spheres of its configuration (count; 0 if unknown)
  double max_d = 0;                   ///< the largest d term of any logged genome (m)
  double target_distance = 0;         ///< distance from the origin to the target (m; 0 if unknown)
  int32_t population = 0;             ///< genomes per generation (count)
  int32_t generations_requested = 0;  ///< generations the run was started for (count)
  int32_t steps = 0;                  ///< physics steps per evaluation (count)
  double dt = 0;                      ///< physics step (s)
  std::string config_json;            ///< the resolved configuration of its last run_t (JSON text,
                                      ///< without a log continuation: log_continuation.hpp)
  /// Set when the log begins at a later generation than 0 (continued from a portable
  /// checkpoint; its earlier generations are in the run's earlier compact result).
  std::optional<LogContinuation> continues;
  std::vector<GenerationRecord> generations;  ///< in generation order, one per logged generation
  std::vector<ChampionRecord> champions;      ///< in generation order, one per generation whose champion was logged
  /// Per genome id with a logged pose stream: the lowest centre height of each sphere over the stream (m).
  std::map<int64_t, std::vector<double>> min_center_z;
  int64_t undecodable = 0;  ///< robozoo messages that failed to decode (count)
  bool truncated = false;   ///< the log ends inside an event

  /// Every requested generation is in the log, 0 to generations_requested - 1.
  bool complete() const;
};

/// Sets what `s` derives from its run_t fields and configuration text: arm,
/// max_spheres, target_distance (a configuration this robozoo cannot read
/// leaves the arm to the regime alone and the other two 0).
void apply_run_configuration(RunSummary& s);

/// Summarises a log already read. Throws std::invalid_argument naming `path`
/// when it holds no decodable ROBOZOO_RUN, or runs with different ids.
RunSummary summarize_run(const LogContents& log, const std::string& path);
/// The best-of-run champion: the highest fitness, and among equals the earliest
/// generation (the one whose pose stream was logged when it became champion).
/// nullptr when no champion was logged.
const ChampionRecord* best_of_run(const RunSummary& run);

}  // namespace robozoo
