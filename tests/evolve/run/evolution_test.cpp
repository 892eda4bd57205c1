#include "evolve/run/evolution.hpp"

#include <fcntl.h>  // tests/support/subprocess.hpp uses open()
#include <gtest/gtest.h>

#include <filesystem>
#include <vector>

#include "evolve/run/checkpoint.hpp"
#include "evolve/run/evaluator.hpp"
#include "tests/support/subprocess.hpp"

namespace robozoo {
namespace {

using robozoo::testing::TempDir;

RunConfig small_run() {
  RunConfig c;
  c.seed = 7;
  c.neat.population = 16;
  c.generations = 3;
  c.eval.sim.steps = 300;
  return c;
}

// Each generation's timings split its wall time: the parts are disjoint, so
// the serial part holds them all; only the run's last generation waits for its
// last (background) checkpoint, and that wait is not counted as serial.
TEST(Evolution, StepTimingsSplitTheGenerationAndTheFinalWaitIsApart) {
  for (const bool background : {true, false}) {
    TempDir dir;
    const RunConfig c = small_run();
    InProcessEvaluator evaluator(c.eval);
    EvolveOptions o;
    o.log_path = dir / "run.lcmlog";
    o.background_checkpoint = background;
    Evolution evo(c, o, evaluator);
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
      if (!last) EXPECT_EQ(t.final_checkpoint, 0.0) << "generation " << g;
      // In the background the last write is still going when the wait starts;
      // at once, it was written within `checkpoint` and nothing is left to wait for.
      if (last && background) EXPECT_GT(t.final_checkpoint, 0.0);
      if (last && !background) EXPECT_LT(t.final_checkpoint, t.checkpoint);
      EXPECT_DOUBLE_EQ(t.serial(), t.total - t.evaluate - t.final_checkpoint);
      EXPECT_GE(t.serial() + 1e-9, t.messages + t.trajectory + t.breeding + t.checkpoint) << "generation " << g;
      EXPECT_GT(t.evaluate, 0.0);
    }
  }
}

}  // namespace
}  // namespace robozoo
