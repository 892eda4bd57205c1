#pragma once
// The experiment page's thumbnail strips (/zoo.json): per arm, the best-of-run
// robots of the trials known from compact results, in their starting pose, by
// fitness (best first), as the zoo sheets of robozoo-render show them. Each
// robot is grown and evaluated again by this build (evolve/run/champion_log's replay_champion,
// no pose stream) and shown only when it gives the committed fitness; the
// others are listed with the reason. Made once and kept until a result
// changes (60 trials: a few seconds).
#include <mutex>
#include <string>

#include "view/feed/experiment_watch.hpp"

namespace robozoo::view {

class ZooStrips {
 public:
  /// {"arms": [{"arm", "robots": [{"name", "seed", "fitness", "c" (x, y, z per
  /// sphere, m), "r" (m), "leaf"}]}], "refused": ["name: why"]}.
  std::string json(const ExperimentWatch& watch);

 private:
  std::mutex mutex_;
  std::string key_, json_;
};

}  // namespace robozoo::view
