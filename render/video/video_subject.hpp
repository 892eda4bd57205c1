#pragma once
// Choosing what a behaviour video shows: the robot, its trajectory and the
// target, from what a log or the bus delivered.
#include "runlog/read/run_record.hpp"
#include "render/video/video.hpp"

namespace robozoo::render {

/// The robot's card, the run's target and the genome's trajectory
/// (genome_trajectory: its poses, a copy's poses, or re-simulation). Throws
/// std::invalid_argument when the genome has no morphology, std::runtime_error
/// when re-simulation cannot reproduce it. `resimulate`: ignore logged poses.
VideoSubject make_video_subject(const RunRecord& run, const GenomeRecord& genome, bool resimulate = false);

}  // namespace robozoo::render
