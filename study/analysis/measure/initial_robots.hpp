#pragma once
// What generation 0 of an arm grows: the robots of the arm's initial genomes
// (random weights on its start topology), grown by the real growth code. A
// check of the prediction that HyperNEAT's fully recurrent start gives the
// experimental regime a head start (more robots beyond the root, more with a
// joint and a distance sensor) before any selection.
#include <cstdint>

#include "evolve/config/run_config.hpp"

namespace robozoo {

struct InitialRobotShares {
  int64_t genomes = 0;             ///< generation-0 genomes grown (count)
  int64_t beyond_root = 0;         ///< robots with more than the root sphere (count)
  int64_t with_joint = 0;          ///< robots with at least one joint after pruning (count)
  int64_t joint_and_distance = 0;  ///< robots with a joint and a distance sensor (count)
  int64_t simulated = 0;           ///< robots that earn simulation (all four r rewards and a distance sensor)
  double mean_spheres = 0.0;       ///< spheres per robot (count)
  double mean_links = 0.0;         ///< link genes per genome (count)
};

/// Grows `genomes` generation-0 genomes of `config`'s regime and start
/// topology (initial_genome with config.neat, one generator seeded with
/// `seed`), as Population's first generation makes them.
InitialRobotShares initial_robot_shares(const RunConfig& config, int64_t genomes, uint64_t seed);

}  // namespace robozoo
