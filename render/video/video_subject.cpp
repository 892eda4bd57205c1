#include "render/video/video_subject.hpp"

#include "render/scene/robot_card.hpp"
#include "runlog/robots/trajectory.hpp"

namespace robozoo::render {

VideoSubject make_video_subject(const RunRecord& run, const GenomeRecord& genome, bool resimulate) {
  VideoSubject s;
  s.card = make_card(run, genome);
  s.target = run_target(run.run);
  s.trajectory = genome_trajectory(run, genome, resimulate);
  return s;
}

}  // namespace robozoo::render
