#pragma once
// The compact result of a run whose log does not begin at generation 0: a run
// continued from a portable checkpoint on a machine without its log
// (study/experiment/portable_checkpoint.hpp) logs generations k.. only, and the
// generations 0..k-1 come with it as an earlier compact result, kept beside
// the log (<log>.earlier.json). The run's compact result is the two merged,
// after checking that they are one run: the same run id, software version,
// seed, regime, sizes and configuration (but the generations requested, which
// an extended run raises), generations numbered 0..k-1 then k.. without a gap,
// evaluations and best-so-far fitness going on exactly where the earlier result
// ends (the log's continuation says where: log_continuation.hpp). The merge is
// the compact result of the uninterrupted run, field for field and bit for bit,
// except evolve_seconds (wall time: the continued run's checkpoint's, which
// counts the time before the move too).
#include <string>

#include "evolve/record/checkpoint.hpp"
#include "evolve/record/run_results.hpp"

namespace robozoo {

/// Where the earlier generations' compact result of a continued log lives: `log_path` + ".earlier.json".
std::string earlier_results_path_for(const std::string& log_path);

/// `earlier` (generations 0..k-1) and `later` (from a log continued at k)
/// as one compact result. Throws std::invalid_argument naming `what` and the
/// first field that breaks continuity.
RunResults merge_run_results(const RunResults& earlier, const RunResults& later, const std::string& what);

/// The compact result of the run logged at `log_path`: results_from_log, and
/// for a log that continues a run (RunSummary::continues), merged with its
/// earlier result (earlier_results_path_for). Throws like read_run_results and
/// merge_run_results, naming the files.
RunResults run_results_of_log(const std::string& log_path);

/// The same for the generations the checkpoint `c` of that log holds: the
/// first c.log_bytes bytes of the log (what follows is a generation not yet
/// finished), with the checkpoint's wall time; for a log continued here that
/// holds no generation yet, the earlier result alone. std::runtime_error when
/// the log is shorter than the checkpoint says.
RunResults run_results_up_to(const std::string& log_path, const Checkpoint& c);

}  // namespace robozoo
