#pragma once
// Choosing what a behaviour video shows: the robot, its trajectory and the
// target, from what a log or the bus delivered.
#include "render/run_record.hpp"
#include "render/video.hpp"

namespace robozoo::render {

/// The target position of a run (sim.target_x/y/z of run_t.config_json).
/// Throws std::invalid_argument when the configuration does not parse.
Eigen::Vector3d run_target(const run_t& run);

/// The trajectory comes from the genome's logged pose stream; else from the
/// stream of an earlier champion of the run with the same genes (NEAT copies
/// champions under fresh ids, and evolve logs a trajectory once); else the
/// genome is re-simulated. Throws std::invalid_argument when the genome has
/// no morphology, std::runtime_error when re-simulation cannot reproduce it.
/// `resimulate`: ignore logged poses and re-simulate.
VideoSubject make_video_subject(const RunRecord& run, const GenomeRecord& genome, bool resimulate = false);

}  // namespace robozoo::render
