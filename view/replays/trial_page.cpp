#include "view/replays/trial_page.hpp"

#include <unistd.h>

#include <filesystem>
#include <stdexcept>

#include "evolve/run/champion_log.hpp"
#include "evolve/run/run_results.hpp"
#include "view/replays/export.hpp"

namespace robozoo::view {

namespace {

/// A temporary folder holding a log named after the trial (the page shows its name), removed with its object.
struct TemporaryLog {
  std::string dir, path;
  explicit TemporaryLog(const std::string& trial) {
    std::string tmpl = (std::filesystem::temp_directory_path() / "robozoo-view-trial-XXXXXX").string();
    if (::mkdtemp(tmpl.data()) == nullptr) throw std::runtime_error("cannot create a temporary folder " + tmpl);
    dir = tmpl;
    path = dir + "/" + trial + "-best-of-run.lcmlog";
  }
  ~TemporaryLog() {
    std::error_code ec;
    std::filesystem::remove_all(dir, ec);
  }
  TemporaryLog(const TemporaryLog&) = delete;
  TemporaryLog& operator=(const TemporaryLog&) = delete;
};

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
    TemporaryLog champion(name);
    write_champion_log(read_run_results(result), champion.path);
    o.log = champion.path;
    return HttpReply{200, "text/html; charset=utf-8", offline_page(dirs, champion_frames(o)), ""};
  } catch (const std::exception& e) {
    return not_found(name + ": " + e.what());
  }
}

}  // namespace robozoo::view
