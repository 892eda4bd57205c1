#include "evolve/run/evolution.hpp"

#include <fcntl.h>  // tests/support/subprocess.hpp uses open()
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "evolve/io/event_log.hpp"
#include "evolve/io/log_compare.hpp"
#include "evolve/record/checkpoint.hpp"
#include "evolve/run/evaluator.hpp"
#include "evolve/run/pool_evaluator.hpp"
#include "tests/support/evolve_runs.hpp"
#include "tests/support/small_run.hpp"
#include "tests/support/subprocess.hpp"

namespace robozoo {
namespace {

using robozoo::testing::TempDir;

/// A run in which new champions reach the simulator (so trajectories are logged).
RunConfig run_with_trajectories() { return robozoo::testing::small_run_config(5); }

EvolveOptions options(const std::string& log, bool background_checkpoint, bool overlap_trajectory) {
  EvolveOptions o;
  o.log_path = log;
  o.background_checkpoint = background_checkpoint;
  o.overlap_trajectory = overlap_trajectory;
  return o;
}

// Each generation's timings split its wall time: the parts are disjoint, so
// the serial part holds them all; only the run's last generation waits for its
// last (background) checkpoint, and that wait is not counted as serial.
TEST(Evolution, StepTimingsSplitTheGenerationAndTheFinalWaitIsApart) {
  for (const bool background : {true, false}) {
    TempDir dir;
    const RunConfig c = run_with_trajectories();
    InProcessEvaluator evaluator(c.eval);
    Evolution evo(c, options(dir / "run.lcmlog", background, false), evaluator);
    std::vector<ProgressReport> reports;
    evo.run([&](const ProgressReport& r) {
      reports.push_back(r);
      if (static_cast<int>(reports.size()) == c.generations) {
        // The run's last generation returns with its last checkpoint on disk.
        EXPECT_TRUE(read_checkpoint(dir / "run.lcmlog.checkpoint").finished) << "background " << background;
      }
    });
    ASSERT_EQ(static_cast<int>(reports.size()), c.generations);
    for (size_t g = 0; g < reports.size(); ++g) {
      const StepTimings& t = reports[g].timings;
      const bool last = g + 1 == reports.size();
      if (!last) {
        EXPECT_EQ(t.final_checkpoint, 0.0) << "generation " << g;
      }
      // In the background the last write is still going when the wait starts;
      // at once, it was written within `checkpoint` and nothing is left to wait for.
      if (last && background) {
        EXPECT_GT(t.final_checkpoint, 0.0);
      }
      if (last && !background) {
        EXPECT_LT(t.final_checkpoint, t.checkpoint);
      }
      EXPECT_DOUBLE_EQ(t.serial(), t.total - t.evaluate - t.final_checkpoint);
      EXPECT_GE(t.serial() + 1e-9, t.messages + t.trajectory + t.breeding + t.checkpoint) << "generation " << g;
      EXPECT_GT(t.evaluate, 0.0);
    }
  }
}

/// Runs `c` to its end, or `stop_after` steps then settle() (or, `failing`,
/// only wait_for_checkpoint()), into `log`.
void evolve(const RunConfig& c, const std::string& log, bool overlap, int stop_after = -1, bool resume = false,
            bool failing = false) {
  PoolEvaluator evaluator(2, c.eval);  // worker processes: rank 0 simulates only the trajectory
  EvolveOptions o = options(log, overlap, overlap);
  o.resume = resume;
  Evolution evo(c, o, evaluator);
  for (int g = 0; (stop_after < 0 || g < stop_after) && evo.step({}); ++g) {
  }
  if (failing)
    evo.wait_for_checkpoint();
  else
    evo.settle();
}

// A caller that read the checkpoint already (robozoo-evolve --resume, for the
// run's configuration) hands it over: the run resumes from that reading, not
// from the file, and logs what an uninterrupted run logs.
TEST(Evolution, ResumesFromTheCheckpointItIsGiven) {
  TempDir dir;
  const RunConfig c = run_with_trajectories();
  evolve(c, dir / "whole.lcmlog", false);
  const std::string log = dir / "resumed.lcmlog";
  evolve(c, log, false, 2);
  ASSERT_EQ(checkpoint_path_for(log), log + ".checkpoint");
  EvolveOptions o = options(log, false, false);
  o.resume = true;
  o.checkpoint = read_checkpoint(checkpoint_path_for(log));
  ASSERT_EQ(o.checkpoint->population.generation, 2);
  // Spoil the file: a second reading of it would fail.
  std::ofstream(checkpoint_path_for(log)) << "{ not json";
  PoolEvaluator evaluator(2, c.eval);
  Evolution evo(c, o, evaluator);
  EXPECT_TRUE(evo.resumed());
  EXPECT_EQ(evo.generation(), 2);
  while (evo.step({})) {
  }
  evo.settle();
  EXPECT_EQ(first_log_difference(read_event_log(dir / "whole.lcmlog"), read_event_log(log)), "");
  EXPECT_TRUE(read_checkpoint(checkpoint_path_for(log)).finished);
}

// robozoo-evolve --mpi re-simulates a new champion while the next generation is
// evaluated; its poses and that generation's checkpoint come later, but the log
// and the checkpoints are those of a run that does it within the generation.
TEST(Evolution, OverlappedTrajectoryGivesTheSameLogAndCheckpoint) {
  TempDir dir;
  const RunConfig c = run_with_trajectories();
  evolve(c, dir / "plain.lcmlog", false);
  evolve(c, dir / "overlapped.lcmlog", true);
  const LogContents plain = read_event_log(dir / "plain.lcmlog");
  EXPECT_GT(robozoo::testing::count_channel(plain, "ROBOZOO_POSE"), 0u);  // trajectories were logged
  EXPECT_EQ(first_log_difference(plain, read_event_log(dir / "overlapped.lcmlog")), "");
  const Checkpoint a = read_checkpoint(dir / "plain.lcmlog.checkpoint");
  const Checkpoint b = read_checkpoint(dir / "overlapped.lcmlog.checkpoint");
  EXPECT_TRUE(b.finished);
  EXPECT_EQ(a.log_bytes, b.log_bytes);
  EXPECT_EQ(a.log_events, b.log_events);
  EXPECT_EQ(a.rng_state, b.rng_state);
  EXPECT_EQ(a.last_champion_hash, b.last_champion_hash);
  EXPECT_EQ(a.evaluations, b.evaluations);
}

// Two simulations at once in one process would differ (ODE's random constraint
// order is process-wide): the overlap is refused with an in-process evaluator.
TEST(Evolution, OverlappedTrajectoryRefusesAnEvaluatorSimulatingInThisProcess) {
  TempDir dir;
  const RunConfig c = run_with_trajectories();
  InProcessEvaluator evaluator(c.eval);
  EXPECT_THROW(Evolution(c, options(dir / "run.lcmlog", false, true), evaluator), std::invalid_argument);
  EXPECT_FALSE(std::filesystem::exists(dir / "run.lcmlog"));
}

// Stopped between generations (as a signal or a failure stops it), the
// overlapped run finishes the pending poses and checkpoints every generation
// done: the log ends where the checkpoint says, and resuming gives the whole run.
TEST(Evolution, OverlappedRunStoppedMidwayCheckpointsAllItDidAndResumes) {
  TempDir dir;
  const RunConfig c = run_with_trajectories();
  evolve(c, dir / "whole.lcmlog", false);
  for (int stop_after = 1; stop_after < c.generations; ++stop_after) {
    const std::string log = dir / ("stopped" + std::to_string(stop_after) + ".lcmlog");
    evolve(c, log, true, stop_after);
    const Checkpoint k = read_checkpoint(log + ".checkpoint");
    EXPECT_EQ(k.population.generation, stop_after);
    EXPECT_FALSE(k.finished);
    EXPECT_EQ(k.log_bytes, static_cast<int64_t>(std::filesystem::file_size(log))) << "stopped after " << stop_after;
    EXPECT_EQ(k.log_events, static_cast<int64_t>(read_event_log(log).records.size()));
    evolve(c, log, true, -1, true);
    EXPECT_EQ(first_log_difference(read_event_log(dir / "whole.lcmlog"), read_event_log(log)), "")
        << "stopped after " << stop_after;
  }
}

// A failing run does not wait for the champion still simulating: the
// checkpoint holds the generations before it, and resuming redoes that one.
TEST(Evolution, OverlappedRunFailingMidwayCheckpointsTheWholeGenerationsAndResumes) {
  TempDir dir;
  const RunConfig c = run_with_trajectories();
  evolve(c, dir / "whole.lcmlog", false);
  bool left_one_out = false;
  for (int stop_after = 1; stop_after < c.generations; ++stop_after) {
    const std::string log = dir / ("failed" + std::to_string(stop_after) + ".lcmlog");
    evolve(c, log, true, stop_after, false, true);
    const Checkpoint k = read_checkpoint(log + ".checkpoint");
    EXPECT_GE(k.population.generation, stop_after - 1);
    EXPECT_LE(k.population.generation, stop_after);
    left_one_out |= k.population.generation == stop_after - 1;
    evolve(c, log, true, -1, true);
    EXPECT_EQ(first_log_difference(read_event_log(dir / "whole.lcmlog"), read_event_log(log)), "")
        << "failed after " << stop_after;
  }
  EXPECT_TRUE(left_one_out);  // some stop found a champion still simulating
}

}  // namespace
}  // namespace robozoo
