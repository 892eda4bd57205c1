// Robots from compact results: the committed paper-size results (M2) give
// their best-of-run robots again, the same on any number of threads, in
// Figure 4's order and with its captions.
#include "render/results/result_robots.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "evolve/messages/build.hpp"
#include "evolve/run/evaluator.hpp"
#include "evolve/run/evolution.hpp"
#include "study/analysis/read/continued_results.hpp"
#include "study/experiment/portable_checkpoint.hpp"
#include "tests/support/continued_run.hpp"
#include "tests/support/small_run.hpp"
#include "tests/support/subprocess.hpp"

namespace robozoo::render {
namespace {

namespace fs = std::filesystem;
using namespace robozoo::testing;

const std::string kM2 = std::string(ROBOZOO_SOURCE_DIR) + "/media/experiment/paper/m2/results";

TEST(ResultRobots, AFolderGivesItsResultsInSeedOrder) {
  const std::vector<std::string> files = results_files({kM2});
  ASSERT_EQ(files.size(), 60u);
  EXPECT_EQ(fs::path(files[0]).filename(), "feedforward-s1.results.json");
  EXPECT_EQ(fs::path(files[1]).filename(), "feedforward-s5.results.json");  // seeds as numbers
  EXPECT_TRUE(is_results_path(kM2));
  EXPECT_TRUE(is_results_path(files[0]));
  EXPECT_FALSE(is_results_path("run.lcmlog"));
  EXPECT_THROW(results_files({"run.lcmlog"}), std::invalid_argument);
  TempDir empty;
  EXPECT_THROW(results_files({empty.path}), std::invalid_argument);
}

TEST(ResultRobots, TheSameRobotsOnOneThreadAndOnTwo) {
  const std::vector<RunResults> results =
      read_results({kM2 + "/feedforward-s1.results.json", kM2 + "/recurrent-s2.results.json"});
  size_t calls = 0, last = 0;
  const std::vector<ResultRobot> one = result_robots(results, true, 1);
  const std::vector<ResultRobot> two = result_robots(results, true, 2, [&](size_t done, size_t total) {
    ++calls;
    last = done;
    EXPECT_EQ(total, 2u);
  });
  EXPECT_GE(calls, 1u);
  EXPECT_EQ(last, 2u);
  ASSERT_EQ(one.size(), 2u);
  ASSERT_EQ(two.size(), 2u);
  for (size_t i = 0; i < 2; ++i) {
    const GenomeRecord &a = one[i].champion(), &b = two[i].champion();
    EXPECT_EQ(one[i].run_id, results[i].run.run_id);
    EXPECT_EQ(a.genome.fitness, best_of_run(results[i].run)->genome.fitness);
    EXPECT_EQ(a.genome.generation, best_of_run(results[i].run)->generation);
    EXPECT_TRUE(a.champion);
    EXPECT_EQ(a.stream, GenomeRecord::Stream::Complete);
    ASSERT_GT(a.poses.size(), 100u);
    ASSERT_EQ(a.poses.size(), b.poses.size());
    morphology_t ma = a.morphology, mb = b.morphology;
    ma.utime = mb.utime = 0;
    EXPECT_EQ(encode_message(ma), encode_message(mb));
    for (size_t k = 0; k < a.poses.size(); ++k) {
      pose_t pa = a.poses[k], pb = b.poses[k];
      pa.utime = pb.utime = 0;
      ASSERT_EQ(encode_message(pa), encode_message(pb)) << "pose " << k;
    }
  }
  // Without poses: the same robot, no stream (a zoo sheet needs none).
  const std::vector<ResultRobot> bare = result_robots(results, false, 2);
  EXPECT_TRUE(bare[0].champion().poses.empty());
  EXPECT_EQ(bare[0].champion().morphology.spheres.size(), one[0].champion().morphology.spheres.size());
}

TEST(ResultRobots, CaptionsNameArmSeedFitnessSpheresAndJoints) {
  const std::vector<RunResults> results = read_results({kM2 + "/recurrent-s2.results.json"});
  const std::vector<ResultRobot> robots = result_robots(results, false, 1);
  const RobotCard card = result_card(robots[0]);
  ASSERT_EQ(card.caption.size(), 2u);
  EXPECT_EQ(card.caption[0], "recurrent \u00b7 seed 2");
  const morphology_t& m = robots[0].champion().morphology;
  char expect[200];
  std::snprintf(expect, sizeof expect, "fitness %.2f \u00b7 %d sphere%s \u00b7 %d joint%s", card.fitness,
                sphere_count(m), sphere_count(m) == 1 ? "" : "s", joint_count(m), joint_count(m) == 1 ? "" : "s");
  EXPECT_EQ(card.caption[1], expect);
  EXPECT_EQ(card_caption(card), card.caption);
  EXPECT_LE(joint_count(m), sphere_count(m) - 1);
}

TEST(ResultRobots, FigureOrderIsByArmThenFitnessAndPicksRankByFitness) {
  const std::vector<RunResults> results = read_results(results_files({kM2}));
  const std::vector<size_t> order = figure_order(results);
  ASSERT_EQ(order.size(), results.size());
  for (size_t i = 1; i < order.size(); ++i) {
    const RunResults &a = results[order[i - 1]], &b = results[order[i]];
    if (a.run.arm == b.run.arm)
      EXPECT_GE(best_of_run(a.run)->genome.fitness, best_of_run(b.run)->genome.fitness) << i;
    else
      EXPECT_EQ(a.run.arm, "feedforward");
  }
  std::vector<RunResults> ff;
  for (const RunResults& r : results)
    if (r.run.arm == "feedforward") ff.push_back(r);
  ASSERT_EQ(ff.size(), 30u);
  std::vector<double> f;
  for (const RunResults& r : ff) f.push_back(best_of_run(r.run)->genome.fitness);
  std::sort(f.rbegin(), f.rend());
  EXPECT_EQ(best_of_run(ff[pick_result(ff, "best")].run)->genome.fitness, f.front());
  EXPECT_EQ(best_of_run(ff[pick_result(ff, "median")].run)->genome.fitness, f[14]);  // rank 15 of 30
  EXPECT_EQ(best_of_run(ff[pick_result(ff, "worst")].run)->genome.fitness, f.back());
  EXPECT_THROW(pick_result(ff, "mean"), std::invalid_argument);
}

TEST(ResultRobots, ATrialInProgressShowsItsChampionSoFarFromItsPortableCheckpoint) {
  // A small run stopped after 2 of 4 generations, packed as robozoo-experiment --save-checkpoints does.
  TempDir dir;
  const std::string log = dir / "recurrent-s3.lcmlog";
  RunConfig c = robozoo::testing::small_run_config(4);
  c.seed = 3;
  InProcessEvaluator evaluator(c.eval);
  EvolveOptions o;
  o.log_path = log;
  o.run_id = "recurrent-s3";
  {
    Evolution evo(c, o, evaluator);
    evo.step();
    evo.step();
  }
  fs::create_directory(dir / "checkpoints");
  const std::string file = dir / "checkpoints/recurrent-s3.portable-checkpoint";
  write_portable_checkpoint(file, pack_portable_checkpoint(log));
  EXPECT_TRUE(is_results_path(file));
  ASSERT_EQ(results_files({dir / "checkpoints"}), std::vector<std::string>{file});
  const std::vector<RunResults> results = read_results({file});
  ASSERT_EQ(results.size(), 1u);
  EXPECT_EQ(results[0].run.path, file);
  const std::vector<ResultRobot> robots = result_robots(results, true, 1);
  EXPECT_EQ(robots[0].generations, 2);
  EXPECT_EQ(robots[0].planned, 4);
  EXPECT_EQ(robots[0].champion().genome.fitness, best_of_run(results[0].run)->genome.fitness);
  const RobotCard card = result_card(robots[0]);
  ASSERT_EQ(card.caption.size(), 2u);
  EXPECT_NE(card.caption[0].find("seed 3 \u00b7 2 of 4 generations"), std::string::npos) << card.caption[0];

  // The trial finishes; its stale portable checkpoint beside its result is the same run: it counts once.
  {
    o.resume = true;
    Evolution evo(c, o, evaluator);
    while (evo.step()) {
    }
  }
  const std::string result = dir / "recurrent-s3.results.json";
  write_run_results(result, run_results_of_log(log));
  std::vector<std::string> left_out;
  const std::vector<RunResults> once = read_results({file, result}, &left_out);
  ASSERT_EQ(once.size(), 1u);
  EXPECT_EQ(once[0].run.path, result);
  EXPECT_EQ(once[0].run.generations.size(), 4u);
  ASSERT_EQ(left_out.size(), 1u);
  EXPECT_EQ(left_out[0], file + ": the same run as " + result + ", which holds 4 generations");
  // Trials of one name in two milestones (another configuration) are two runs.
  const std::string m3 =
      std::string(ROBOZOO_SOURCE_DIR) + "/media/experiment/paper/m3/results/feedforward-s1.results.json";
  EXPECT_EQ(read_results({kM2 + "/feedforward-s1.results.json", m3}).size(), 2u);
}

TEST(ResultRobots, ARunningExperimentsFolderOfLogsGivesEachTrialsChampionSoFar) {
  // robozoo-experiment's runs folder while it works: a finished trial, one in
  // progress whose log ends mid-event, and one whose log is still empty.
  TempDir dir;
  fs::create_directory(dir / "runs");
  evolve_small_run(dir / "runs/feedforward-s1.lcmlog", "feedforward-s1", 2, 1, Regime::FeedForward);
  RunConfig c = small_run_config(4);
  c.seed = 3;
  InProcessEvaluator evaluator(c.eval);
  for (const char* name : {"recurrent-s3", "recurrent-s10"}) {
    EvolveOptions o;
    o.log_path = dir / ("runs/" + std::string(name) + ".lcmlog");
    o.run_id = name;
    Evolution evo(c, o, evaluator);
    if (std::string(name) == "recurrent-s3") {
      evo.step();
      evo.step();
    }
  }
  // Half an event more at the end of the trial in progress, as while it is written.
  const std::string in_progress = dir / "runs/recurrent-s3.lcmlog";
  const std::string whole = read_file(in_progress);
  const std::string partial = whole + whole.substr(0, 40);
  std::ofstream(in_progress, std::ios::binary | std::ios::trunc) << partial;

  // A fourth trial in its first generation: its log holds the run message
  // only (the first event of an LCM log: a 28-byte header whose last two
  // big-endian words are the channel's and the data's lengths).
  const std::string first_log = read_file(dir / "runs/feedforward-s1.lcmlog");
  ASSERT_GT(first_log.size(), 28u);
  const auto be32 = [&](size_t at) {
    uint32_t v = 0;
    for (size_t k = 0; k < 4; ++k) v = (v << 8) | static_cast<uint8_t>(first_log[at + k]);
    return v;
  };
  const size_t first_event = 28 + be32(20) + be32(24);
  ASSERT_LT(first_event, first_log.size());
  std::ofstream(dir / "runs/feedforward-s14.lcmlog", std::ios::binary) << first_log.substr(0, first_event);

  std::vector<std::string> files = results_files({dir / "runs"});
  ASSERT_EQ(files.size(), 4u);
  ASSERT_EQ(fs::path(files[1]).filename(), "feedforward-s14.lcmlog");
  files.erase(files.begin() + 1);  // read on its own below
  EXPECT_EQ(fs::path(files[0]).filename(), "feedforward-s1.lcmlog");
  EXPECT_EQ(fs::path(files[1]).filename(), "recurrent-s3.lcmlog");
  EXPECT_EQ(fs::path(files[2]).filename(), "recurrent-s10.lcmlog");  // seeds as numbers
  // Without a list of what is left out, the log that has no run yet is an error naming it.
  try {
    read_results(files);
    ADD_FAILURE() << "read a log without a run";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("recurrent-s10.lcmlog"), std::string::npos) << e.what();
  }
  std::vector<std::string> left_out;
  const std::vector<RunResults> drawn = read_results(files, &left_out);
  ASSERT_EQ(left_out.size(), 1u);
  EXPECT_EQ(left_out[0].rfind(files[2] + ": ", 0), 0u) << left_out[0];
  ASSERT_EQ(drawn.size(), 2u);
  EXPECT_EQ(drawn[1].run.path, in_progress);
  const std::string started = dir / "runs/feedforward-s14.lcmlog";
  EXPECT_EQ(read_results({started}).front().run.run_id, "feedforward-s1");  // readable, no champion
  left_out.clear();
  EXPECT_TRUE(read_results({started}, &left_out).empty());
  EXPECT_EQ(left_out, std::vector<std::string>{started + ": no finished generation yet"});
  const std::vector<ResultRobot> robots = result_robots(drawn, false, 2);
  EXPECT_EQ(robots[0].generations, 2);
  EXPECT_EQ(robots[0].planned, 2);
  EXPECT_EQ(robots[1].generations, 2);
  EXPECT_EQ(robots[1].planned, 4);
  for (size_t i = 0; i < 2; ++i)
    EXPECT_EQ(robots[i].champion().genome.fitness, best_of_run(drawn[i].run)->genome.fitness);
  EXPECT_NE(result_card(robots[1]).caption[0].find("seed 3 \u00b7 2 of 4 generations"), std::string::npos)
      << result_card(robots[1]).caption[0];
  // Compact results in a folder come before its logs: the logs are not listed then.
  std::ofstream(dir / "runs/recurrent-s3.portable-checkpoint") << "";
  EXPECT_EQ(results_files({dir / "runs"}), std::vector<std::string>{dir / "runs/recurrent-s3.portable-checkpoint"});
}

TEST(ResultRobots, AContinuedLogInTheFolderCountsItsEarlierGenerations) {
  // A trial moved to this machine by its portable checkpoint: its log begins
  // at generation 3, and generations 0-2 come beside it (<log>.earlier.json).
  TempDir dir;
  evolve_whole_and_continued(small_run_config(5), "recurrent-s7", dir / "whole/recurrent-s7.lcmlog",
                             dir / "before/recurrent-s7.lcmlog", dir / "runs/recurrent-s7.lcmlog", 3);

  const std::vector<std::string> files = results_files({dir / "runs"});
  ASSERT_EQ(files, std::vector<std::string>{dir / "runs/recurrent-s7.lcmlog"});
  const std::vector<RunResults> results = read_results(files);
  const RunResults whole = read_results({dir / "whole/recurrent-s7.lcmlog"}).front();
  ASSERT_EQ(results[0].run.generations.size(), 5u);
  EXPECT_EQ(best_of_run(results[0].run)->genome.fitness, best_of_run(whole.run)->genome.fitness);
  EXPECT_EQ(best_of_run(results[0].run)->generation, best_of_run(whole.run)->generation);
  const std::vector<ResultRobot> robots = result_robots(results, false, 1);
  EXPECT_EQ(robots[0].champion().genome.fitness, best_of_run(whole.run)->genome.fitness);
}

}  // namespace
}  // namespace robozoo::render
