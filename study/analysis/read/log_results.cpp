#include "study/analysis/read/log_results.hpp"

#include <filesystem>

#include "evolve/record/checkpoint.hpp"
#include "runlog/read/log_reader.hpp"

namespace robozoo {

RunSummary summarize_run_file(const std::string& path) { return summarize_run(scan_event_log(path).contents, path); }

RunResults results_from_log(const std::string& log_path) {
  RunResults r;
  r.run = compact_summary(summarize_run_file(log_path));
  const std::string cp = checkpoint_path_for(log_path);
  try {
    if (std::filesystem::exists(cp)) {
      r.evolve_seconds = read_checkpoint(cp).elapsed_seconds;
      r.has_evolve_seconds = true;
    }
  } catch (const std::exception&) {
    // The time is informative only: an unreadable checkpoint leaves it out.
  }
  return r;
}

}  // namespace robozoo
