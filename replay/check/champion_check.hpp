#pragma once
// Checking one logged genome: decode it, grow it and compare the morphology
// field by field, re-simulate it and compare every logged pose with the state
// at that step, re-evaluate it and compare the fitness.
#include <cstdint>
#include <string>
#include <vector>

#include "evolve/config/run_config.hpp"
#include "evolve/io/event_log.hpp"
#include "runlog/read/log_index.hpp"
#include "replay/check/recompute_cache.hpp"
#include "replay/compare/value_compare.hpp"

namespace robozoo::replay {

/// What a genome's check must find of its trajectory (log_structure decides it
/// from the generation's messages).
enum class TrajectoryRule : int8_t {
  None,      ///< no pose may be logged for it (not a new champion, or not simulated)
  Complete,  ///< every pose of its trajectory, once and in order
  MayBeCut,  ///< in order, but the log may end before the trajectory does (or no rule is known)
  Damaged,   ///< due, but events near it do not decode: a gap is a problem of the input, not a divergence
  Lossy,     ///< received from a lossy bus: poses in order, each at most once; gaps are loss (poses_missing)
};

struct ChampionResult {
  enum class Status { Ok, Diverged, Unusable };
  Status status = Status::Ok;
  std::string run_id;
  int32_t generation = -1;
  int64_t genome_id = -1;
  bool champion = true;
  std::vector<std::string> problems;  ///< why (part of) it could not be checked; Unusable when not empty
  // What was recomputed
  int spheres = 0;                     ///< spheres grown (count)
  int64_t same_genes_as = -1;          ///< an earlier genome with the same genes whose growth and
                                       ///< evaluation were re-used, -1 if none
  int32_t same_genes_generation = -1;  ///< its generation
  bool morphology_logged = false;
  bool morphology_ok = false;
  int64_t poses_logged = 0;           ///< decodable poses of this genome in the log (count)
  int64_t poses_expected = 0;         ///< poses its trajectory has at the run's pose_every (count), 0 if none is due
  int64_t poses_compared = 0;         ///< (count)
  int64_t poses_missing = 0;          ///< TrajectoryRule::Lossy: poses of the trajectory not received (count)
  int64_t poses_diverged = 0;         ///< poses with at least one differing value (count)
  int64_t first_divergent_step = -1;  ///< -1 if none
  bool fitness_compared = false;
  double logged_fitness = 0.0, recomputed_fitness = 0.0;
  int logged_outcome = -1, recomputed_outcome = -1;
  // Every difference
  std::vector<Mismatch> mismatches;  ///< the first ones, in order of discovery
  int64_t mismatch_count = 0;        ///< all of them (count)
  int64_t values_compared = 0;       ///< (count)
  double max_error = 0.0;            ///< largest value_error over the real values compared
};

const char* status_name(ChampionResult::Status s);  ///< "ok", "diverged", "unusable"

struct ChampionCheckParams {
  double tolerance = 0.0;  ///< 0: bit for bit; else the largest value_error allowed (dimensionless)
  size_t keep = 20;        ///< mismatches kept with their details (count)
};

/// Checks `g` against a re-computation with `config` (the configuration of
/// its run's ROBOZOO_RUN). Bad input becomes problems in the result, never an
/// exception. With a cache, the growth and evaluation of genes already
/// recomputed are re-used (poses are always re-simulated). `trajectory`: whether
/// its logged poses must be its whole trajectory (each step once, in order).
ChampionResult check_champion(const LogContents& log, const LogIndex& index, const LoggedGenome& g,
                              const RunConfig& config, const ChampionCheckParams& params,
                              RecomputeCache* cache = nullptr, TrajectoryRule trajectory = TrajectoryRule::MayBeCut);

}  // namespace robozoo::replay
