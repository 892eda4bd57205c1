#pragma once
// The champion-change analysis of the paper's section 4: when a new champion
// arises, is its morphology topologically different from the previous
// champion's, and by how much did the fitness improve?
//
// A new champion arises at generation g when g's champion is fitter than
// generation g - 1's (evaluation is deterministic and NEAT copies the champion
// unchanged, so the generation best never falls and a champion whose genes
// changed without a gain in fitness is not a new champion). By default only
// changes between two simulated champions count: the jumps of the r term
// before a robot is first sent to the simulator (e.g. 4 to 15 points) measure
// the reward for having parts, not the optimisation of robots that the paper's
// question is about.
#include <cstdint>
#include <vector>

#include "evolve/record/run_summary.hpp"
#include "study/analysis/measure/topology.hpp"

namespace robozoo {

struct ChampionChangeParams {
  TopologyOptions topology;    ///< what counts as the same topology
  bool simulated_only = true;  ///< count only changes between two simulated champions
};

struct ChampionChange {
  int32_t generation = 0;         ///< generation of the new champion
  int64_t previous_id = -1;       ///< genome id of generation - 1's champion
  int64_t genome_id = -1;         ///< genome id of the new champion
  double previous_fitness = 0;    ///< fitness units
  double fitness = 0;             ///< fitness units
  double improvement = 0;         ///< fitness - previous_fitness (fitness units, > 0)
  bool topology_changed = false;  ///< the two sphere trees differ (topology.hpp)
};

struct ChampionChanges {
  std::vector<ChampionChange> changes;  ///< in generation order
  int32_t not_simulated = 0;            ///< fitness gains left out because a champion was not simulated (count)
  int32_t unknown = 0;  ///< fitness gains left out: a champion or its morphology missing from the log (count)
};

/// The new champions of `run`.
ChampionChanges champion_changes(const RunSummary& run, const ChampionChangeParams& params = {});

}  // namespace robozoo
