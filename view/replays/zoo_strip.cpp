#include "view/replays/zoo_strip.hpp"

#include <algorithm>
#include <cstdio>
#include <vector>

#include "evolve/run/champion_log.hpp"
#include "evolve/record/run_results.hpp"
#include "runlog/robots/leaf_spheres.hpp"
#include "study/analysis/read/continued_results.hpp"
#include "study/experiment/portable_checkpoint.hpp"

namespace robozoo::view {

namespace {

/// What a trial's robot is made from: its result file and that file's stamp,
/// or its log and its best fitness so far (the champion changes only with it).
std::string source_key(const TrialProgress& t) {
  if (!t.results_path.empty()) return "result\n" + t.results_path + "\n" + t.results_stamp;
  char best[64];
  std::snprintf(best, sizeof best, "%.17g", t.best_so_far.back());
  return "log\n" + t.log_path + "\n" + best;
}

nlohmann::json robot_of(const TrialProgress& t, const RunResults& r) {
  const ChampionReplay c = replay_champion(r, false);
  nlohmann::json robot = {{"name", t.name},
                          {"seed", t.seed},
                          {"fitness", c.genome.fitness},
                          {"generations", r.run.generations.size()},
                          {"planned", r.run.generations_requested}};
  nlohmann::json centres = nlohmann::json::array(), radii = nlohmann::json::array();
  for (const sphere_t& s : c.morphology.spheres) {
    for (double v : s.center) centres.push_back(v);
    radii.push_back(s.radius);
  }
  robot["c"] = centres;
  robot["r"] = radii;
  robot["leaf"] = leaf_spheres(c.morphology);
  return robot;
}

}  // namespace

std::string ZooStrips::json(const ExperimentWatch& watch) {
  std::vector<TrialProgress> trials = watch.trials();
  // A trial's log without a finished generation has no champion yet.
  trials.erase(std::remove_if(trials.begin(), trials.end(),
                              [](const TrialProgress& t) { return t.results_path.empty() && t.best_so_far.empty(); }),
               trials.end());
  std::lock_guard<std::mutex> lock(mutex_);
  std::map<std::string, Made> kept;
  for (const TrialProgress& t : trials) {
    const std::string key = source_key(t);
    auto old = made_.find(t.name);
    if (old != made_.end() && old->second.key == key) {
      kept[t.name] = std::move(old->second);
      continue;
    }
    Made m;
    m.key = key;
    try {
      const RunResults r =
          t.results_path.empty() ? run_results_of_log(t.log_path) : read_results_or_portable_checkpoint(t.results_path);
      m.robot = robot_of(t, r);
    } catch (const std::exception& e) {
      m.robot = nullptr;
      m.refused = t.name + ": " + e.what();
    }
    kept[t.name] = std::move(m);
  }
  made_ = std::move(kept);

  std::map<std::string, std::vector<nlohmann::json>> arms;
  nlohmann::json refused = nlohmann::json::array();
  for (const TrialProgress& t : trials) {
    const Made& m = made_.at(t.name);
    if (m.robot.is_null())
      refused.push_back(m.refused);
    else
      arms[t.arm].push_back(m.robot);
  }
  nlohmann::json out = {{"arms", nlohmann::json::array()}, {"refused", refused}};
  for (auto& [arm, robots] : arms) {
    std::stable_sort(robots.begin(), robots.end(), [](const nlohmann::json& a, const nlohmann::json& b) {
      return a["fitness"].get<double>() > b["fitness"].get<double>();
    });
    out["arms"].push_back({{"arm", arm}, {"robots", robots}});
  }
  return out.dump();
}

}  // namespace robozoo::view
