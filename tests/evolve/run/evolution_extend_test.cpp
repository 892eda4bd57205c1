// A resumed run given more generations (EvolveOptions::generations) ends as an
// uninterrupted run of that many generations: message for message, whether it
// had finished (its last generation evaluated again to breed the next) or was
// stopped part way. The run messages logged before the extension say the
// generations the run was started for; nothing else differs.
#include "evolve/run/evolution.hpp"

#include <fcntl.h>  // tests/support/subprocess.hpp uses open()
#include <gtest/gtest.h>

#include "evolve/io/event_log.hpp"
#include "evolve/io/log_compare.hpp"
#include "evolve/record/checkpoint.hpp"
#include "evolve/run/evaluator.hpp"
#include "tests/support/extended_run.hpp"
#include "tests/support/small_run.hpp"
#include "tests/support/subprocess.hpp"

namespace robozoo {
namespace {

using robozoo::testing::TempDir;

EvolveOptions options(const std::string& log, bool resume, int32_t generations = 0) {
  EvolveOptions o;
  o.log_path = log;
  o.resume = resume;
  o.generations = generations;
  return o;
}

/// The uninterrupted run of `generations`.
LogContents whole_run(const TempDir& dir, int generations) {
  const RunConfig c = robozoo::testing::small_run_config(generations);
  InProcessEvaluator evaluator(c.eval);
  Evolution evo(c, options(dir / "whole.lcmlog", false), evaluator);
  evo.run({});
  return read_event_log(dir / "whole.lcmlog");
}

TEST(EvolutionExtend, AFinishedRunExtendedEqualsTheUninterruptedRun) {
  TempDir dir;
  const RunConfig c = robozoo::testing::small_run_config(3);
  InProcessEvaluator evaluator(c.eval);
  {
    Evolution evo(c, options(dir / "run.lcmlog", false), evaluator);
    evo.run({});
  }
  ASSERT_TRUE(read_checkpoint(dir / "run.lcmlog.checkpoint").finished);
  {
    Evolution evo(c, options(dir / "run.lcmlog", true, 6), evaluator);
    EXPECT_TRUE(evo.resumed());
    EXPECT_FALSE(evo.finished());
    EXPECT_EQ(evo.start_generation(), 3);
    EXPECT_EQ(evo.config().generations, 6);
    evo.run({});
  }
  const Checkpoint cp = read_checkpoint(dir / "run.lcmlog.checkpoint");
  EXPECT_TRUE(cp.finished);
  EXPECT_EQ(cp.config["generations"], 6);
  const LogContents extended = read_event_log(dir / "run.lcmlog"), whole = whole_run(dir, 6);
  EXPECT_EQ(robozoo::testing::count_run_generations(extended), 6u);
  EXPECT_EQ(first_log_difference(robozoo::testing::run_requested_as(extended, 6), whole), "");
}

TEST(EvolutionExtend, ARunStoppedPartWayExtendedEqualsTheUninterruptedRun) {
  TempDir dir;
  const RunConfig c = robozoo::testing::small_run_config(4);
  InProcessEvaluator evaluator(c.eval);
  {
    Evolution evo(c, options(dir / "run.lcmlog", false), evaluator);
    ASSERT_TRUE(evo.step({}));
    ASSERT_TRUE(evo.step({}));
    evo.wait_for_checkpoint();
  }  // stopped after generation 1 of 4
  {
    Evolution evo(c, options(dir / "run.lcmlog", true, 6), evaluator);
    EXPECT_EQ(evo.start_generation(), 2);
    evo.run({});
  }
  EXPECT_EQ(first_log_difference(robozoo::testing::run_requested_as(read_event_log(dir / "run.lcmlog"), 6),
                                 whole_run(dir, 6)),
            "");
}

TEST(EvolutionExtend, ARunCannotBeCutShort) {
  TempDir dir;
  const RunConfig c = robozoo::testing::small_run_config(3);
  InProcessEvaluator evaluator(c.eval);
  {
    Evolution evo(c, options(dir / "run.lcmlog", false), evaluator);
    evo.run({});
  }
  try {
    Evolution evo(c, options(dir / "run.lcmlog", true, 2), evaluator);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("started for 3 generations; it can be extended, not cut to 2"),
              std::string::npos)
        << e.what();
  }
  // The same number is a plain resume of a finished run.
  Evolution same(c, options(dir / "run.lcmlog", true, 3), evaluator);
  EXPECT_TRUE(same.finished());
}

}  // namespace
}  // namespace robozoo
