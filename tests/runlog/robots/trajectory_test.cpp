#include "runlog/robots/trajectory.hpp"

#include <fcntl.h>  // tests/support/subprocess.hpp uses open()
#include <gtest/gtest.h>

#include "runlog/read/log_source.hpp"
#include "tests/render/fixtures.hpp"
#include "tests/render/messages.hpp"
#include "tests/support/subprocess.hpp"

namespace robozoo {
namespace {

using robozoo::testing::TempDir;

TEST(Trajectory, InterpolatesBetweenPosesAndClampsAtTheEnds) {
  const Trajectory t = trajectory_from_poses(
      {render::testing::pose_message("r", 0, 1, 0, 0.0), render::testing::pose_message("r", 0, 1, 10, 1.0)}, 4);
  EXPECT_DOUBLE_EQ(t.start_time(), 0.0);
  EXPECT_DOUBLE_EQ(t.end_time(), 0.1);
  EXPECT_NEAR(t.sample(0.05)[0].x(), 0.5, 1e-12);
  EXPECT_NEAR(t.sample(0.025)[1].x(), 0.9 + 0.25, 1e-12);
  EXPECT_EQ(t.sample(-1)[0].x(), 0.0);
  EXPECT_EQ(t.sample(9)[0].x(), 1.0);
}

TEST(Trajectory, RejectsBadStreams) {
  EXPECT_THROW(trajectory_from_poses({}, 4), std::invalid_argument);
  EXPECT_THROW(trajectory_from_poses({render::testing::pose_message("r", 0, 1, 0, 0, 3)}, 4), std::invalid_argument);
  EXPECT_THROW(trajectory_from_poses(
                   {render::testing::pose_message("r", 0, 1, 5), render::testing::pose_message("r", 0, 1, 5)}, 4),
               std::invalid_argument);
}

// Re-simulation with the shared code reproduces the logged poses bit for bit.
TEST(Trajectory, ResimulationMatchesTheLoggedPoses) {
  TempDir dir;
  render::testing::write_small_run(dir / "run.lcmlog");
  const LoadedLog log = load_log(dir / "run.lcmlog");
  const RunRecord& run = *log.runs()[0];
  int checked = 0;
  for (const auto& g : run.genomes) {
    if (g->poses.empty()) continue;
    const Trajectory logged = trajectory_from_poses(g->poses, g->morphology.spheres.size());
    const Trajectory again = simulate_trajectory(run.run, g->genome, g->morphology, 1);
    EXPECT_TRUE(again.resimulated);
    EXPECT_EQ(again.step.back(), logged.step.back());
    for (size_t i = 0; i < logged.step.size(); ++i) {
      const size_t j = static_cast<size_t>(logged.step[i]);  // every step kept: index = step
      ASSERT_EQ(again.step[j], logged.step[i]);
      EXPECT_EQ(again.time[j], logged.time[i]);
      for (size_t s = 0; s < logged.centers[i].size(); ++s) EXPECT_EQ(again.centers[j][s], logged.centers[i][s]);
    }
    ++checked;
  }
  EXPECT_GE(checked, 1);
}

TEST(Trajectory, ResimulationRefusesAnotherRobot) {
  TempDir dir;
  render::testing::write_small_run(dir / "run.lcmlog");
  const LoadedLog log = load_log(dir / "run.lcmlog");
  const RunRecord& run = *log.runs()[0];
  const GenomeRecord& g = *run.genomes.back();
  morphology_t moved = g.morphology;
  moved.spheres[0].center[0] += 0.01;
  EXPECT_THROW(simulate_trajectory(run.run, g.genome, moved), std::runtime_error);
  run_t broken = run.run;
  broken.config_json = "{not json";
  EXPECT_THROW(simulate_trajectory(broken, g.genome, g.morphology), std::invalid_argument);
}

}  // namespace
}  // namespace robozoo
