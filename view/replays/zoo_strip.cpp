#include "view/replays/zoo_strip.hpp"

#include <algorithm>
#include <map>
#include <vector>

#include <nlohmann/json.hpp>

#include "runlog/robots/leaf_spheres.hpp"
#include "evolve/run/champion_log.hpp"
#include "evolve/run/run_results.hpp"
#include "study/experiment/portable_checkpoint.hpp"

namespace robozoo::view {

std::string ZooStrips::json(const ExperimentWatch& watch) {
  std::vector<TrialProgress> trials = watch.trials();
  trials.erase(
      std::remove_if(trials.begin(), trials.end(), [](const TrialProgress& t) { return t.results_path.empty(); }),
      trials.end());
  std::string key;
  for (const TrialProgress& t : trials) key += t.results_path + "\n" + t.results_stamp + "\n";
  std::lock_guard<std::mutex> lock(mutex_);
  if (!json_.empty() && key == key_) return json_;
  std::map<std::string, std::vector<nlohmann::json>> arms;
  nlohmann::json refused = nlohmann::json::array();
  for (const TrialProgress& t : trials) {
    try {
      const RunResults r = read_results_or_portable_checkpoint(t.results_path);
      const ChampionReplay c = replay_champion(r, false);
      nlohmann::json robot = {{"name", t.name}, {"seed", t.seed}, {"fitness", c.genome.fitness}};
      nlohmann::json centres = nlohmann::json::array(), radii = nlohmann::json::array();
      for (const sphere_t& s : c.morphology.spheres) {
        for (double v : s.center) centres.push_back(v);
        radii.push_back(s.radius);
      }
      robot["c"] = centres;
      robot["r"] = radii;
      robot["leaf"] = leaf_spheres(c.morphology);
      arms[t.arm].push_back(robot);
    } catch (const std::exception& e) {
      refused.push_back(t.name + ": " + e.what());
    }
  }
  nlohmann::json out = {{"arms", nlohmann::json::array()}, {"refused", refused}};
  for (auto& [arm, robots] : arms) {
    std::stable_sort(robots.begin(), robots.end(), [](const nlohmann::json& a, const nlohmann::json& b) {
      return a["fitness"].get<double>() > b["fitness"].get<double>();
    });
    out["arms"].push_back({{"arm", arm}, {"robots", robots}});
  }
  key_ = key;
  json_ = out.dump();
  return json_;
}

}  // namespace robozoo::view
