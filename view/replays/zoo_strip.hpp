#pragma once
// The experiment page's thumbnail strips (/zoo.json): per arm, every trial's
// best-of-run robot (its champion so far while it runs) in its starting pose,
// by fitness (best first), as the zoo sheets of robozoo-render show them. A
// trial with a log is read from its log (study's run_results_of_log: a
// continued log with its earlier generations), one known
// from its compact result alone from that. Each robot is grown and evaluated
// again by this build (evolve/run/champion_log's replay_champion, no pose
// stream) and shown only when it gives the recorded fitness; the others are
// listed with the reason. Each trial's robot is kept until its result changes
// or, for a log, its best fitness so far does: a running experiment re-reads
// only the logs whose champion changed (60 trials from scratch: a few seconds).
#include <map>
#include <mutex>
#include <string>

#include <nlohmann/json.hpp>

#include "view/feed/experiment_watch.hpp"

namespace robozoo::view {

class ZooStrips {
 public:
  /// {"arms": [{"arm", "robots": [{"name", "seed", "fitness", "generations",
  /// "planned", "c" (x, y, z per sphere, m), "r" (m), "leaf"}]}], "refused":
  /// ["name: why"]}; "generations" is the trial's finished generations when
  /// its robot was made, "planned" those its run was started for (counts).
  std::string json(const ExperimentWatch& watch);

 private:
  struct Made {
    std::string key;       ///< what it was made from: the file, and its stamp or best fitness so far
    nlohmann::json robot;  ///< null when refused
    std::string refused;   ///< why not shown
  };
  std::mutex mutex_;
  std::map<std::string, Made> made_;  ///< by trial name
};

}  // namespace robozoo::view
