#include "view/replays/trial_page.hpp"

#include <filesystem>
#include <stdexcept>

#include "evolve/record/run_results.hpp"
#include "runlog/read/champion_record.hpp"
#include "study/experiment/portable_checkpoint.hpp"
#include "view/replays/export.hpp"

namespace robozoo::view {

namespace {

HttpReply not_found(const std::string& line) { return HttpReply{404, "text/plain; charset=utf-8", line + "\n", ""}; }

}  // namespace

HttpReply trial_page(const ExperimentWatch& watch, const AssetDirs& dirs, const std::string& name) {
  const std::string log = watch.log_of(name), result = watch.results_of(name);
  try {
    ExportOptions o;
    if (!log.empty()) {
      o.log = log;
      o.allow_truncated = true;  // it may be growing
      return HttpReply{200, "text/html; charset=utf-8", offline_page(dirs, champion_frames(o)), ""};
    }
    if (result.empty()) return not_found("no trial " + name);
    const RunResults r = read_results_or_portable_checkpoint(result);  // run.path, what a refusal names: the file
    const RunRecord run = champion_run_record(replay_champion(r, true), result, &r.run);  // with its curves
    const std::string source = std::filesystem::path(result).filename().string() + " (best of run, simulated again)";
    return HttpReply{200, "text/html; charset=utf-8",
                     offline_page(dirs, genome_frames(run, *run.genomes.front(), source)), ""};
  } catch (const std::exception& e) {
    return not_found(name + ": " + e.what());
  }
}

}  // namespace robozoo::view
