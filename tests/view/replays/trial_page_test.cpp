// The page of one trial of robozoo-view --experiment: a trial known only from
// its compact result shows its best-of-run robot, re-made by this build from
// a real run's result; a result whose fitness this build does not give, and
// an unknown trial, are answered 404 with the reason.
#include "view/replays/trial_page.hpp"

#include <fcntl.h>  // tests/support/subprocess.hpp uses open()
#include <gtest/gtest.h>

#include <filesystem>

#include "evolve/run/evaluator.hpp"
#include "evolve/run/evolution.hpp"
#include "evolve/record/run_results.hpp"
#include "study/analysis/read/log_results.hpp"
#include "study/experiment/portable_checkpoint.hpp"
#include "tests/support/small_run.hpp"
#include "tests/support/subprocess.hpp"

namespace robozoo::view {
namespace {

using robozoo::testing::TempDir;

AssetDirs source_dirs() { return {std::string(ROBOZOO_SOURCE_DIR) + "/view/page", ROBOZOO_THREE_DIR}; }

/// The compact result of a real small run (3 generations, champions simulated).
RunResults real_result(const TempDir& dir) {
  robozoo::testing::evolve_small_run(dir / "recurrent-s7.lcmlog", "recurrent-s7", 3);
  return results_from_log(dir / "recurrent-s7.lcmlog");
}

/// The text of <script type="application/json" id="robozoo-data">.
nlohmann::json inline_data(const std::string& html) {
  const std::string open = "<script type=\"application/json\" id=\"robozoo-data\">";
  const size_t a = html.find(open);
  if (a == std::string::npos) return nullptr;
  const size_t b = html.find("</script>", a);
  return nlohmann::json::parse(html.substr(a + open.size(), b - a - open.size()));
}

TEST(TrialPage, ATrialKnownFromItsResultShowsItsBestOfRunRobotMadeAgain) {
  TempDir runs, logs, results;
  const RunResults r = real_result(runs);
  write_run_results(results / "recurrent-s7.results.json", r);
  ExperimentWatchOptions o;
  o.results_dirs = {results.path};
  const ExperimentWatch watch(logs.path, o);
  const HttpReply page = trial_page(watch, source_dirs(), "recurrent-s7");
  ASSERT_EQ(page.status, 200) << page.body.substr(0, 300);
  EXPECT_EQ(page.content_type, "text/html; charset=utf-8");
  const nlohmann::json frames = inline_data(page.body);
  ASSERT_TRUE(frames.is_array()) << page.body.substr(0, 300);
  // The champion frame names the best-of-run genome, with its committed fitness.
  const ChampionRecord* best = best_of_run(r.run);
  ASSERT_NE(best, nullptr);
  bool champion = false;
  for (const auto& f : frames)
    if (f.value("t", "") == "champions")
      for (const auto& c : f["list"]) {
        EXPECT_EQ(c["id"].get<int64_t>(), best->genome.genome_id) << c;
        EXPECT_EQ(c["fitness"].get<double>(), best->genome.fitness) << c;
        champion = true;
      }
  EXPECT_TRUE(champion) << frames.dump().substr(0, 600);
  // The page names the trial's result; it was made in memory (no temporary folder, no log).
  EXPECT_NE(frames[0].dump().find("recurrent-s7.results.json (best of run, simulated again)"), std::string::npos)
      << frames[0];
  for (const auto& e : std::filesystem::directory_iterator(std::filesystem::temp_directory_path()))
    EXPECT_EQ(e.path().filename().string().rfind("robozoo-view-trial-", 0), std::string::npos) << e.path();

  // A result this build does not reproduce: the reason, no page.
  RunResults changed = r;
  for (auto& c : changed.run.champions)
    if (c.genome.genome_id == best->genome.genome_id) c.genome.fitness += 1;
  write_run_results(results / "recurrent-s7.results.json", changed);
  ExperimentWatch watch2(logs.path, o);
  const HttpReply refused = trial_page(watch2, source_dirs(), "recurrent-s7");
  EXPECT_EQ(refused.status, 404);
  EXPECT_NE(refused.body.find("recurrent-s7: "), std::string::npos) << refused.body;
  EXPECT_NE(refused.body.find("fitness"), std::string::npos) << refused.body;

  const HttpReply unknown = trial_page(watch, source_dirs(), "recurrent-s99");
  EXPECT_EQ(unknown.status, 404);
  EXPECT_EQ(unknown.body, "no trial recurrent-s99\n");
}

TEST(TrialPage, ATrialInProgressKnownFromItsPortableCheckpointShowsItsChampionSoFar) {
  // A small run stopped after 2 of 4 generations, packed as robozoo-experiment --save-checkpoints does.
  TempDir runs, logs, checkpoints;
  RunConfig c = robozoo::testing::small_run_config(4);
  c.seed = 3;
  InProcessEvaluator evaluator(c.eval);
  EvolveOptions eo;
  eo.log_path = runs / "recurrent-s3.lcmlog";
  eo.run_id = "recurrent-s3";
  {
    Evolution evo(c, eo, evaluator);
    evo.step();
    evo.step();
  }
  const PortableCheckpoint packed = pack_portable_checkpoint(runs / "recurrent-s3.lcmlog");
  write_portable_checkpoint(checkpoints / "recurrent-s3.portable-checkpoint", packed);
  ExperimentWatchOptions o;
  o.results_dirs = {checkpoints.path};
  const ExperimentWatch watch(logs.path, o);
  const nlohmann::json summary = nlohmann::json::parse(watch.summary());
  ASSERT_EQ(summary["trials"].size(), 1u) << summary.dump();
  EXPECT_EQ(summary["trials"][0]["name"], "recurrent-s3");
  EXPECT_EQ(summary["trials"][0]["source"], "checkpoint");
  EXPECT_EQ(summary["trials"][0]["generations"], 2);
  const HttpReply page = trial_page(watch, source_dirs(), "recurrent-s3");
  ASSERT_EQ(page.status, 200) << page.body.substr(0, 300);
  const nlohmann::json frames = inline_data(page.body);
  const ChampionRecord* best = best_of_run(packed.earlier.run);
  ASSERT_NE(best, nullptr);
  bool champion = false;
  for (const auto& f : frames)
    if (f.value("t", "") == "champions")
      for (const auto& ch : f["list"]) {
        EXPECT_EQ(ch["id"].get<int64_t>(), best->genome.genome_id) << ch;
        EXPECT_EQ(ch["fitness"].get<double>(), best->genome.fitness) << ch;
        champion = true;
      }
  EXPECT_TRUE(champion);
  EXPECT_NE(frames[0].dump().find("recurrent-s3.portable-checkpoint"), std::string::npos) << frames[0];
}

}  // namespace
}  // namespace robozoo::view
