// robozoo-experiment on a finished experiment with more --generations: the
// trials of the arms asked for continue from their checkpoints and end as
// uninterrupted runs of that many generations would (message for message; the
// run messages written before the extension say the generations they were
// started for); their compact results are rewritten; the other arms are left
// alone; a trial without its checkpoint is a clear error, and a trial known
// only from its compact result is done when it reached the generations asked
// (its time, for --status and the estimate, is the result's).
#include <gtest/gtest.h>

#include <filesystem>

#include "evolve/record/run_results.hpp"
#include "evolve/io/event_log.hpp"
#include "evolve/io/log_compare.hpp"
#include "evolve/record/checkpoint.hpp"
#include "tests/support/evolve_runs.hpp"
#include "tests/support/extended_run.hpp"
#include "tests/support/subprocess.hpp"

namespace robozoo {
namespace {

using namespace robozoo::testing;
namespace fs = std::filesystem;

std::vector<std::string> driver(const std::string& out, int generations, const std::vector<std::string>& extra = {}) {
  std::vector<std::string> a = {bin("robozoo-experiment"),
                                "--out",
                                out,
                                "--workers",
                                "1",
                                "--progress-interval",
                                "0",
                                "--trials",
                                "1",
                                "--population",
                                "12",
                                "--steps",
                                "300",
                                "--generations",
                                std::to_string(generations)};
  a.insert(a.end(), extra.begin(), extra.end());
  return a;
}

TEST(ExperimentExtendCli, MoreGenerationsExtendTheArmsAskedForFromTheirCheckpoints) {
  TempDir dir, ref;
  const auto first = run_shell(join(driver(dir.path, 3)));
  ASSERT_EQ(first.status, 0) << first.output;
  const std::string ff_log = dir / "feedforward-s1.lcmlog", rec_log = dir / "recurrent-s2.lcmlog";
  const std::string ff_results = dir / "results/feedforward-s1.results.json";
  const std::string rec_results = dir / "results/recurrent-s2.results.json";
  ASSERT_EQ(read_run_results(rec_results).run.generations.size(), 3u);
  const std::string ff_before = read_file(ff_log), ff_results_before = read_file(ff_results);

  // Only the recurrent arm to 5 generations.
  const auto more = run_shell(join(driver(dir.path, 5, {"--arms", "recurrent"})));
  ASSERT_EQ(more.status, 0) << more.output;
  EXPECT_NE(more.output.find("0 finished (skipped), 1 to resume, 0 to start"), std::string::npos) << more.output;
  EXPECT_NE(more.output.find("recurrent-s2: resuming after generation 3 (to 5)"), std::string::npos) << more.output;
  EXPECT_TRUE(read_checkpoint(rec_log + ".checkpoint").finished);
  EXPECT_EQ(read_file(ff_log), ff_before);
  EXPECT_EQ(read_file(ff_results), ff_results_before);
  // Its compact result was rewritten at its new end.
  const RunResults rec = read_run_results(rec_results);
  EXPECT_EQ(rec.run.generations.size(), 5u);
  EXPECT_EQ(rec.run.generations_requested, 5);
  EXPECT_TRUE(rec.run.complete());

  // The extended trial is the uninterrupted 5-generation run, message for message.
  const auto reference = run_shell(
      join({bin("robozoo-evolve"), "--log", ref / "rec.lcmlog", "--regime", "recurrent", "--seed", "2", "--population",
            "12", "--generations", "5", "--steps", "300", "--workers", "1", "--run-id", "recurrent-s2", "--quiet"}));
  ASSERT_EQ(reference.status, 0) << reference.output;
  const LogContents extended = read_event_log(rec_log), whole = read_event_log(ref / "rec.lcmlog");
  EXPECT_EQ(first_log_difference(run_requested_as(extended, 5), whole), "");
  // Without the rewrite, the only differences are the run messages before the extension.
  EXPECT_NE(first_log_difference(extended, whole).find("ROBOZOO_RUN"), std::string::npos);

  // The whole experiment at 3 generations: the extended trial counts as done.
  const auto again = run_shell(join(driver(dir.path, 3)));
  EXPECT_EQ(again.status, 0) << again.output;
  EXPECT_NE(again.output.find("2 finished (skipped), 0 to resume, 0 to start"), std::string::npos) << again.output;
  EXPECT_EQ(read_run_results(rec_results).run.generations.size(), 5u);
  // ... and at 4, the 5-generation trial is done and only the feed-forward one is extended.
  const auto four = run_shell(join(driver(dir.path, 4)));
  EXPECT_EQ(four.status, 0) << four.output;
  EXPECT_NE(four.output.find("1 finished (skipped), 1 to resume, 0 to start"), std::string::npos) << four.output;
  EXPECT_EQ(read_run_results(ff_results).run.generations.size(), 4u);
}

TEST(ExperimentExtendCli, WithoutItsCheckpointATrialCannotBeExtended) {
  TempDir dir, other;
  ASSERT_EQ(run_shell(join(driver(dir.path, 2))).status, 0);
  fs::remove(dir / "feedforward-s1.lcmlog.checkpoint");
  const auto r = run_shell(join(driver(dir.path, 3, {"--arms", "feedforward"})));
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("feedforward-s1.lcmlog has no checkpoint"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("can be neither resumed nor extended"), std::string::npos) << r.output;

  // Another machine with the compact results only: done at their generations, not extensible.
  const std::string results = dir / "results";
  const auto done = run_shell(join(driver(other / "exp", 2, {"--results", results})));
  EXPECT_EQ(done.status, 0) << done.output;
  EXPECT_NE(done.output.find("2 finished (skipped), 0 to resume, 0 to start"), std::string::npos) << done.output;
  EXPECT_FALSE(file_exists(other / "exp/recurrent-s2.lcmlog"));
  // --status there takes each trial's time from its compact result (it says "?" when the
  // result has none), and estimates from the timed trials alone.
  const std::string timed = other / "timed";
  fs::create_directories(timed);
  for (const char* trial : {"feedforward-s1", "recurrent-s2"}) {
    RunResults r = read_run_results(results + "/" + trial + ".results.json");
    r.has_evolve_seconds = std::string(trial) == "feedforward-s1";
    r.evolve_seconds = 3600;
    write_run_results(timed + "/" + trial + ".results.json", r);
  }
  const auto status = run_shell(join(driver(other / "exp", 2, {"--results", timed, "--status"})));
  EXPECT_EQ(status.status, 0) << status.output;
  EXPECT_NE(status.output.find("feedforward-s1        finished         2/2      1h00m"), std::string::npos)
      << status.output;
  EXPECT_NE(status.output.find("recurrent-s2          finished         2/2      ?"), std::string::npos)
      << status.output;
  const auto beyond = run_shell(join(driver(other / "exp", 3, {"--results", results})));
  EXPECT_EQ(beyond.status, 2) << beyond.output;
  EXPECT_NE(beyond.output.find("feedforward-s1.results.json holds feedforward-s1 at 2 generations, but its log and "
                               "checkpoint are not in"),
            std::string::npos)
      << beyond.output;
}

}  // namespace
}  // namespace robozoo
