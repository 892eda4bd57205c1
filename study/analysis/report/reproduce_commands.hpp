#pragma once
// The commands that make the runs a report compares, read from the runs
// themselves (arm, seed, population, generations requested, steps), not from a
// template: when an arm's seeds are those robozoo-experiment gives its trials
// 1..N (trial_seed) and its runs share their sizes, one robozoo-experiment line
// makes them (one line for both arms when they agree on N and the sizes);
// otherwise one robozoo-evolve line per run, with that run's seed.
#include <string>
#include <vector>

#include "study/analysis/compare/experiment_analysis.hpp"

namespace robozoo {

/// Shell lines (comments start with '#'): the compared arms' runs into
/// `log_dir`, then `stats_command`, then the paper's full size (marked as not run).
std::vector<std::string> reproduce_commands(const ExperimentAnalysis& a, const std::string& log_dir,
                                            const std::string& stats_command);

}  // namespace robozoo
