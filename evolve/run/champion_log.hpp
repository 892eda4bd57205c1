#pragma once
// A compact result's best-of-run champion grown, evaluated and simulated again
// by this build, its fitness checked against the committed one: in memory
// (replay_champion, what robozoo-render and robozoo-view draw) or as a log
// that robozoo-render, robozoo-replay and robozoo-view read
// (write_champion_log, robozoo-evolve champion): the one generation of a
// one-generation run (run_t with the result's configuration, generations 1;
// generation_t with the counts of the generation the champion won; its genome
// with the committed fitness, r, d and outcome; its morphology; its pose
// stream). Its generation is 0 in that log; its run id, genome id and species
// are the result's.
#include <functional>
#include <string>
#include <vector>

#include "evolve/record/run_results.hpp"
#include "robozoo/cppn_genome_t.hpp"
#include "robozoo/generation_t.hpp"
#include "robozoo/morphology_t.hpp"
#include "robozoo/pose_t.hpp"
#include "robozoo/run_t.hpp"

namespace robozoo {

/// The champion again, as the messages of its one-generation log (generation 0,
/// utime the time of the replay).
struct ChampionReplay {
  int32_t generation = 0;     ///< generation the champion won in its run
  int32_t generations = 0;    ///< generations its run was started for (count)
  run_t run;                  ///< the result's configuration, generations 1
  generation_t summary;       ///< the counts of the generation it won
  cppn_genome_t genome;       ///< with the committed (= this build's) fitness, r, d and outcome
  morphology_t morphology;    ///< the robot grown again
  std::vector<pose_t> poses;  ///< its pose stream (empty: not asked for, or never simulated)
};

/// Grows, evaluates and (with `poses`) simulates the champion again. Throws
/// std::invalid_argument when the result has no best-of-run champion or its
/// configuration cannot be read, and std::runtime_error when this build does
/// not reproduce the committed fitness, r, d or outcome (naming the result's
/// file, the genome and both values).
ChampionReplay replay_champion(const RunResults& results, bool poses = true);

/// replay_champion of each result, `jobs` at once (0: one per core) in child
/// processes (ODE's stepping is one per process), or in this one when `jobs`
/// is 1; the same replays for any `jobs`, in the order of `results`. `done`
/// (may be empty) is called from the calling thread as replays finish (count
/// done, total). When some result fails, throws the first failure in the
/// order of `results` (as replay_champion would) after the others have finished.
std::vector<ChampionReplay> replay_champions(const std::vector<RunResults>& results, bool poses, int jobs,
                                             const std::function<void(size_t, size_t)>& done = {});

/// A generation of a compact result as its run logged it (generation_t of run
/// `run_id`, stamped `utime`).
generation_t generation_message_of(const GenerationRecord& r, const std::string& run_id, int64_t utime);

struct ChampionLogInfo {
  int32_t generation = 0;  ///< generation the champion won in its run
  int64_t genome_id = -1;
  double fitness = 0;  ///< committed fitness (fitness units)
  size_t poses = 0;    ///< poses written (count)
};

/// Writes the log at `log_path` (replay_champion's exceptions, and
/// std::runtime_error when the log cannot be written).
ChampionLogInfo write_champion_log(const RunResults& results, const std::string& log_path);

}  // namespace robozoo
