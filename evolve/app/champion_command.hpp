#pragma once
// robozoo-evolve champion RESULT --log OUT: a compact result's best-of-run
// champion as a one-generation log (evolve/run/champion_log.hpp) that
// robozoo-render video, robozoo-replay check and robozoo-view read.
#include <CLI/CLI.hpp>

#include <string>

namespace robozoo {

struct ChampionOptions {
  std::string results_file;  ///< a compact result (*.results.json)
  std::string log_path;      ///< the log to write
  bool force = false;        ///< accept a result written by another robozoo version
};

void add_champion_options(CLI::App& app, ChampionOptions& o);
/// Returns the exit status: 0 written, 1 this build does not reproduce the
/// champion or the log cannot be written, 2 bad input.
int run_champion_command(const ChampionOptions& o);

}  // namespace robozoo
