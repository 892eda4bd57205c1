#pragma once
// A run's log read into its summary and its compact results (the formats are
// evolve/record/run_summary.hpp and evolve/record/run_results.hpp); the log is read with
// runlog/, the one reader of logs.
#include <string>

#include "evolve/record/run_results.hpp"
#include "evolve/record/run_summary.hpp"

namespace robozoo {

/// Reads the log at `path` with runlog's reader (past damage: the events after
/// garbage are read too) and summarises it (std::runtime_error when unreadable).
RunSummary summarize_run_file(const std::string& path);

/// The compact results of the log at `log_path`: its summary, reduced, and the
/// wall time of `<log_path>.checkpoint` when there is one.
RunResults results_from_log(const std::string& log_path);

}  // namespace robozoo
