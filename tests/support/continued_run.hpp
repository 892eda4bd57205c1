#pragma once
// Test support: one run evolved twice, to compare a continued log with the
// uninterrupted one: whole, and stopped after some generations, then moved by
// its portable checkpoint (study/experiment/portable_checkpoint.hpp) to a new
// log that begins there (its earlier generations' result beside it,
// <log>.earlier.json) and run to the end, as a trial moved to another machine.
#include <filesystem>
#include <string>

#include "evolve/config/run_config.hpp"
#include "evolve/run/evaluator.hpp"
#include "evolve/run/evolution.hpp"
#include "study/experiment/portable_checkpoint.hpp"

namespace robozoo::testing {

/// Evolves `c` as run `run_id` into `whole_log`; again into `before_log` for
/// `stop_after` generations; then continues that from its portable checkpoint
/// in `continued_log` to the end. Creates the logs' folders.
inline void evolve_whole_and_continued(const RunConfig& c, const std::string& run_id, const std::string& whole_log,
                                       const std::string& before_log, const std::string& continued_log,
                                       int stop_after) {
  for (const std::string& log : {whole_log, before_log})
    std::filesystem::create_directories(std::filesystem::path(log).parent_path());
  InProcessEvaluator evaluator(c.eval);
  EvolveOptions o;
  o.run_id = run_id;
  o.log_path = whole_log;
  Evolution(c, o, evaluator).run();
  o.log_path = before_log;
  {
    Evolution evo(c, o, evaluator);
    for (int g = 0; g < stop_after; ++g) evo.step();
  }
  unpack_portable_checkpoint(pack_portable_checkpoint(before_log), continued_log);
  o.log_path = continued_log;
  o.resume = true;
  Evolution(c, o, evaluator).run();
}

}  // namespace robozoo::testing
