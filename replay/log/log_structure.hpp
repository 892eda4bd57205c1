#pragma once
// The messages of a log as robozoo-evolve writes them, proved one by one.
// For each run (events of several runs may interleave):
//
//   ROBOZOO_RUN                       first event of the run; repeated once before
//                                     each generation (for late joiners), every
//                                     repeat equal to the first except utime
//   ROBOZOO_GENERATION                exactly one per generation, numbered 0, 1, ...
//   ROBOZOO_GENOME, ROBOZOO_MORPHOLOGY  the champion first (its id is champion_id, its
//                                     fitness best_fitness), each genome followed by its
//                                     morphology; every other genome too with publish_all
//   ROBOZOO_POSE ...                  the champion's trajectory, when its genes differ
//                                     from the previous generation's champion and it
//                                     was simulated (the poses themselves: champion_check)
//
// and generation_t's figures: evaluations cumulative (+ population each
// generation), best_so_far the running maximum of best_fitness, outcome counts
// adding up to the population (with publish_all, equal to the genomes' outcomes),
// 1 <= num_species <= population.
//
// A generation cut short at the very end of the log is no divergence when the
// log is truncated or its run unfinished (a log copied while evolve writes): it
// is reported as an input problem instead.
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "evolve/config/run_config.hpp"
#include "evolve/io/event_log.hpp"
#include "replay/check/champion_check.hpp"
#include "runlog/read/log_index.hpp"

namespace robozoo::replay {

/// A message that is not what robozoo-evolve writes at that place.
struct LogDifference {
  int64_t eventnum = -1;  ///< the event's number in the log; -1: the end of the log
  std::string channel;    ///< the event's channel (or the missing message's)
  std::string run_id;
  int32_t generation = -1;  ///< the generation it belongs to, -1 if none
  std::string field;        ///< the field or property, e.g. "best_fitness", "channel", "poses"
  std::string logged;       ///< what the log holds
  std::string expected;     ///< what it should hold
  std::string rule;         ///< the rule it breaks, one sentence
};

struct StructureReport {
  std::vector<LogDifference> differences;  ///< in log order
  std::vector<InputProblem> incomplete;    ///< a last generation cut short by the end of the log
  /// Per genome event (LogIndex::events index) of a champion: its trajectory rule.
  std::map<size_t, TrajectoryRule> trajectory;
  int32_t generations = 0;  ///< generation_t messages proved (count)
};

/// Proves the order and counts of a log's messages and generation_t's
/// figures. `config_of_run`: each run's configuration (from its first
/// ROBOZOO_RUN); runs missing from it are skipped (their genomes are unusable
/// anyway). `truncated`: the log's last event is cut.
StructureReport check_log_structure(const LogContents& log, const LogIndex& index,
                                    const std::map<std::string, RunConfig>& config_of_run, bool truncated);

/// "event 812 (ROBOZOO_GENERATION) run r gen 3 best_fitness: logged X, expected Y (rule)".
std::string describe(const LogDifference& d);

}  // namespace robozoo::replay
