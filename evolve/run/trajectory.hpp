#pragma once
// A champion's trajectory as robozoo logs it: the pose at step 0, at every
// pose_every-th step, and at the last step simulated (whatever pose_every;
// evolve/sim/episode/trajectory_sampler).
// robozoo-evolve publishes it for each new champion; robozoo-replay check
// re-creates it to prove that every logged pose is there, once and in order.
#include <cstdint>
#include <string>
#include <vector>

#include "evolve/cppn/genome.hpp"
#include "evolve/growth/robot.hpp"
#include "evolve/sim/episode/simulation.hpp"
#include "evolve/sim/episode/trajectory_sampler.hpp"
#include "robozoo/pose_t.hpp"

namespace robozoo {

/// A champion's trajectory as pose messages (the motion itself, for drawing,
/// is runlog's Trajectory).
struct PoseStream {
  std::vector<pose_t> poses;  ///< in step order (trajectory_steps), utime 0 (set when sent)
  SimResult result;           ///< the simulation's result (d, outcome, steps run)
};

/// The champion's genes as the log carries them (its id and the links' birth
/// generations left out), hashed: robozoo-evolve logs a champion's trajectory
/// when this differs from the previous generation's champion's (NEAT copies a
/// champion unchanged under a fresh id, and the copy's trajectory is logged
/// already), and robozoo-replay check proves it from the logged genomes.
uint64_t trajectory_key(const Genome& champion);

/// Simulates `robot` with `sim` and returns its logged poses (sample_trajectory
/// at pose_every) and its result. Throws std::invalid_argument when pose_every < 1.
PoseStream simulate_pose_stream(const Robot& robot, const SimParams& sim, int pose_every, const std::string& run_id,
                                int32_t generation, int64_t genome_id);

}  // namespace robozoo
