#include "render/video/video_subject.hpp"

#include <fcntl.h>  // tests/support/subprocess.hpp uses open()
#include <gtest/gtest.h>

#include "runlog/read/log_source.hpp"
#include "runlog/robots/selection.hpp"
#include "tests/render/fixtures.hpp"
#include "tests/render/messages.hpp"
#include "tests/support/subprocess.hpp"

namespace robozoo::render {
namespace {

using robozoo::testing::TempDir;

TEST(VideoSubject, LoggedPosesACopysStreamOrResimulation) {
  TempDir dir;
  testing::write_small_run(dir / "run.lcmlog");
  const LoadedLog log = load_log(dir / "run.lcmlog");
  const std::vector<Pick> best = best_of_run(log.runs());
  ASSERT_EQ(best.size(), 1u);
  const GenomeRecord& champ = *best[0].genome;
  const Trajectory logged = trajectory_from_poses(champ.poses, champ.morphology.spheres.size());

  const VideoSubject own = make_video_subject(*best[0].run, champ);
  EXPECT_FALSE(own.trajectory.resimulated);
  EXPECT_EQ(own.trajectory.step, logged.step);
  EXPECT_EQ(own.card.genome_id, champ.genome.genome_id);
  EXPECT_EQ(own.target, Eigen::Vector3d(50, 0, 0));

  GenomeRecord copy = champ;  // NEAT's unchanged copy of a champion: same genes, no poses of its own
  copy.poses.clear();
  copy.genome.genome_id += 100000;
  const VideoSubject borrowed = make_video_subject(*best[0].run, copy);
  EXPECT_FALSE(borrowed.trajectory.resimulated);
  EXPECT_EQ(borrowed.trajectory.step, logged.step);

  RunRecord alone;  // a run where no genome has poses: re-simulated
  alone.run = best[0].run->run;
  const VideoSubject again = make_video_subject(alone, copy);
  EXPECT_TRUE(again.trajectory.resimulated);
  EXPECT_EQ(again.trajectory.end_time(), logged.end_time());
  EXPECT_EQ(again.trajectory.sample(1.0), logged.sample(1.0));  // step 100: in both, bit for bit

  const VideoSubject forced = make_video_subject(*best[0].run, champ, true);
  EXPECT_TRUE(forced.trajectory.resimulated);
  EXPECT_EQ(forced.trajectory.sample(2.0), logged.sample(2.0));
}

TEST(VideoSubject, TargetFromTheRunsConfiguration) {
  RunConfig c;
  c.eval.sim.target_x = -4;
  c.eval.sim.target_y = 2.5;
  run_t r = testing::run_message("r");
  r.config_json = config_to_json(c).dump();
  EXPECT_EQ(run_target(r), Eigen::Vector3d(-4, 2.5, 0));
  r.config_json = "{\"no_such_key\": 1}";
  EXPECT_THROW(run_target(r), std::invalid_argument);
}

TEST(VideoSubject, NeedsAMorphology) {
  RunRecord run;
  run.run = testing::run_message("r");
  GenomeRecord g;
  g.genome = testing::genome_message("r", 0, 1, 1.0);
  EXPECT_THROW(make_video_subject(run, g), std::invalid_argument);
}

}  // namespace
}  // namespace robozoo::render
