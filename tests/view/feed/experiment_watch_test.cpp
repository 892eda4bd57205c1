// robozoo-view --experiment: the folder's trials read as their logs grow, each
// arm's mean and standard error per generation (hand-computed), the t-tests
// per generation, the trials' states and the folders that are no experiment.
#include <fcntl.h>  // tests/support/subprocess.hpp uses open()
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "evolve/io/event_log.hpp"
#include "evolve/record/run_results.hpp"
#include "tests/render/messages.hpp"
#include "tests/support/subprocess.hpp"
#include "view/feed/experiment_watch.hpp"

namespace robozoo::view {
namespace {

namespace fs = std::filesystem;
using namespace robozoo::render::testing;
using robozoo::testing::TempDir;

/// A trial log whose generations, from `first` on, have these best-so-far values; the run was
/// started for `planned` generations.
void write_trial(const std::string& path, const std::vector<double>& bsf, int planned = 5, int first = 0) {
  EventLogWriter w = EventLogWriter::create(path);
  run_t run = run_message("t");
  run.generations = planned;
  append(w, kChannelRun, run);
  for (size_t g = 0; g < bsf.size(); ++g) {
    generation_t m = generation_message("t", first + static_cast<int32_t>(g), 1);
    m.best_so_far_fitness = bsf[g];
    append(w, kChannelGeneration, m);
  }
}

std::string bytes_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

void put(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

/// A compact result of a recurrent trial with these best-so-far values, started for `planned` generations.
void write_result(const std::string& path, int64_t seed, const std::vector<double>& bsf, int planned = 2) {
  RunResults r;
  RunSummary& s = r.run;
  s.path = "recurrent-s" + std::to_string(seed) + ".lcmlog";
  s.run_id = "recurrent-s" + std::to_string(seed);
  s.software_version = "0123456789ab";
  s.seed = seed;
  s.regime = 1;
  s.arm = "recurrent";
  s.population = 10;
  s.generations_requested = planned;
  s.steps = 100;
  s.dt = 0.01;
  s.config_json = "{}";
  for (size_t g = 0; g < bsf.size(); ++g) {
    GenerationRecord rec;
    rec.generation = static_cast<int32_t>(g);
    rec.best_fitness = rec.best_so_far_fitness = bsf[g];
    rec.evaluations = 10 * static_cast<int64_t>(g + 1);
    s.generations.push_back(rec);
  }
  write_run_results(path, r);
}

TrialProgress trial(const std::string& arm, std::vector<double> bsf) {
  TrialProgress t;
  t.arm = arm;
  t.best_so_far = std::move(bsf);
  return t;
}

TEST(ArmCurves, MeanAndStandardErrorByHand) {
  // feedforward: generation 0 {1, 3}: mean 2, s.d. sqrt(2), s.e. sqrt(2)/sqrt(2) = 1;
  // generation 1 {2, 4}: 3 +- 1; generation 2 {3} alone: 3, no s.e.
  // recurrent: {2, 2}: 2 +- 0; {4, 6}: 5 +- 1; {6, 8}: 7 +- 1.
  const std::vector<TrialProgress> t = {trial("recurrent", {2, 4, 6}), trial("feedforward", {1, 2, 3}),
                                        trial("feedforward", {3, 4}), trial("recurrent", {2, 6, 8})};
  const std::vector<ArmCurve> c = arm_curves(t);
  ASSERT_EQ(c.size(), 2u);
  EXPECT_EQ(c[0].arm, "feedforward");
  EXPECT_EQ(c[0].mean, (std::vector<double>{2, 3, 3}));
  EXPECT_DOUBLE_EQ(c[0].se[0], 1.0);
  EXPECT_DOUBLE_EQ(c[0].se[1], 1.0);
  EXPECT_TRUE(std::isnan(c[0].se[2]));
  EXPECT_EQ(c[0].n, (std::vector<int>{2, 2, 1}));
  EXPECT_EQ(c[1].arm, "recurrent");
  EXPECT_EQ(c[1].mean, (std::vector<double>{2, 5, 7}));
  EXPECT_EQ(c[1].se, (std::vector<double>{0, 1, 1}));

  // Student's t at generation 1: pooled variance (2 + 2) / 2 = 2, t = (3 - 5) / sqrt(2 (1/2 + 1/2)) = -sqrt(2),
  // df 2: p = 1 - |t| / sqrt(t^2 + 2) = 1 - sqrt(2)/2. Generation 0: equal means, p 1. Generation 2: one trial.
  const std::vector<double> p = generation_p_values(t, "feedforward", "recurrent");
  ASSERT_EQ(p.size(), 3u);
  EXPECT_NEAR(p[0], 1.0, 1e-12);
  EXPECT_NEAR(p[1], 1.0 - std::sqrt(2.0) / 2.0, 1e-9);
  EXPECT_TRUE(std::isnan(p[2]));
}

TEST(ExperimentWatch, ReadsTheFolderAndFollowsGrowingLogs) {
  TempDir d;
  const std::string ff1 = d / "feedforward-s1.lcmlog", rec2 = d / "recurrent-s2.lcmlog";
  const std::string ff5 = d / "feedforward-s5.lcmlog", rec6 = d / "recurrent-s6.lcmlog";
  write_trial(ff1, {1.0, 1.1}, 2);   // finished
  write_trial(rec2, {5.0, 5.1}, 2);  // finished
  write_trial(ff5, {1.05});          // stopped: old, without a checkpoint
  fs::last_write_time(ff5, fs::file_time_type::clock::now() - std::chrono::hours(1));
  // recurrent-s6 grows: first its first generation and half of its second event.
  write_trial(d / "full.tmp", {5.1, 6.0, 7.0});
  write_trial(d / "one.tmp", {5.1});
  const std::string full = bytes_of(d / "full.tmp"), one = bytes_of(d / "one.tmp");
  fs::remove(d / "full.tmp");
  fs::remove(d / "one.tmp");
  ASSERT_EQ(full.compare(0, one.size(), one), 0) << "a log is not a prefix of its longer self";
  put(rec6, full.substr(0, one.size() + 10));
  std::ofstream(d / "notes.txt") << "not a trial";
  std::ofstream(d / "sideways-s3.lcmlog") << "not an arm";

  ExperimentWatch w(d.path, ExperimentWatchOptions{});
  std::vector<TrialProgress> t = w.trials();
  ASSERT_EQ(t.size(), 4u);
  EXPECT_EQ(t[0].name, "feedforward-s1");
  EXPECT_EQ(t[0].state, "finished");
  EXPECT_EQ(t[1].name, "feedforward-s5");
  EXPECT_EQ(t[1].seed, 5);
  EXPECT_EQ(t[1].state, "stopped");
  EXPECT_EQ(t[3].name, "recurrent-s6");
  EXPECT_EQ(t[3].best_so_far, (std::vector<double>{5.1}));  // the cut event is not read yet
  EXPECT_EQ(t[3].state, "running");
  EXPECT_EQ(t[3].planned, 5);
  EXPECT_EQ(t[3].offset, static_cast<int64_t>(one.size()));

  nlohmann::json s = nlohmann::json::parse(w.summary());
  EXPECT_EQ(s["trials"].size(), 4u);
  EXPECT_EQ(s["arms"][0]["arm"], "feedforward");
  // Generation 0 of feedforward: {1.0, 1.05}: mean 1.025, s.d. 0.05/sqrt(2), s.e. 0.05/sqrt(2)/sqrt(2) = 0.025.
  EXPECT_NEAR(s["arms"][0]["mean"][0].get<double>(), 1.025, 1e-12);
  EXPECT_NEAR(s["arms"][0]["se"][0].get<double>(), 0.025, 1e-12);
  EXPECT_TRUE(s["arms"][0]["se"][1].is_null());  // one trial at generation 1
  // Generation 0: {1.0, 1.05} against {5.0, 5.1}: p far below 0.05; generation 1: one feedforward trial.
  ASSERT_EQ(s["tests"].size(), 1u);
  EXPECT_EQ(s["tests"][0]["significant"], nlohmann::json::array({0}));
  EXPECT_LT(s["tests"][0]["p"][0].get<double>(), 0.001);
  EXPECT_EQ(w.log_of("recurrent-s6"), rec6);
  EXPECT_EQ(w.log_of("recurrent-s9"), "");

  EXPECT_FALSE(w.poll());  // nothing new
  put(rec6, full);         // the rest arrives
  EXPECT_TRUE(w.poll());
  t = w.trials();
  EXPECT_EQ(t[3].best_so_far, (std::vector<double>{5.1, 6.0, 7.0}));
  EXPECT_EQ(t[3].offset, static_cast<int64_t>(full.size()));
  s = nlohmann::json::parse(w.summary());
  EXPECT_EQ(s["trials"][3]["generations"], 3);
  EXPECT_DOUBLE_EQ(s["arms"][1]["mean"][1].get<double>(), (5.1 + 6.0) / 2);
  // A new trial appears.
  write_trial(d / "feedforward-s13.lcmlog", {0.5});
  EXPECT_TRUE(w.poll());
  EXPECT_EQ(w.trials().size(), 5u);
  s = nlohmann::json::parse(w.summary());
  EXPECT_EQ(s["trials"][1]["name"], "feedforward-s5");  // by arm, then seed: s13 after s5
  EXPECT_EQ(s["trials"][2]["name"], "feedforward-s13");
}

TEST(ExperimentWatch, TrialsKnownOnlyFromCompactResultsCountToo) {
  TempDir d, r1, r2;
  write_trial(d / "feedforward-s1.lcmlog", {1.0, 1.1}, 2);
  // Its result is not shown: the log is there.
  write_result(r1 / "feedforward-s1.results.json", 1, {9.0, 9.0});
  write_result(r1 / "recurrent-s2.results.json", 2, {5.0, 5.1});
  // Two results of one trial (two milestones): the one with more generations is shown.
  write_result(r1 / "recurrent-s6.results.json", 6, {4.0});
  write_result(r2 / "recurrent-s6.results.json", 6, {4.0, 4.5, 6.0}, 3);
  std::ofstream(r2 / "recurrent-s10.results.json") << "{\"format\": \"robozoo-run-results\"";
  std::ofstream(r2 / "notes.json") << "{}";

  ExperimentWatchOptions o;
  o.results_dirs = {r1.path, r2.path};
  ExperimentWatch w(d.path, o);
  std::vector<TrialProgress> t = w.trials();
  ASSERT_EQ(t.size(), 3u);
  EXPECT_EQ(t[0].name, "feedforward-s1");
  EXPECT_EQ(t[0].best_so_far, (std::vector<double>{1.0, 1.1}));
  EXPECT_EQ(t[0].results_path, "");
  EXPECT_EQ(t[1].name, "recurrent-s2");
  EXPECT_EQ(t[1].best_so_far, (std::vector<double>{5.0, 5.1}));
  EXPECT_EQ(t[1].state, "finished");
  EXPECT_EQ(t[1].planned, 2);
  EXPECT_EQ(t[1].seed, 2);
  EXPECT_EQ(t[1].arm, "recurrent");
  EXPECT_EQ(t[2].name, "recurrent-s6");
  EXPECT_EQ(t[2].best_so_far, (std::vector<double>{4.0, 4.5, 6.0}));
  EXPECT_EQ(w.results_of("recurrent-s6"), r2 / "recurrent-s6.results.json");
  EXPECT_EQ(w.log_of("recurrent-s6"), "");
  EXPECT_EQ(w.results_of("feedforward-s1"), "");

  nlohmann::json s = nlohmann::json::parse(w.summary());
  ASSERT_EQ(s["trials"].size(), 3u);
  EXPECT_EQ(s["trials"][0]["source"], "log");
  EXPECT_EQ(s["trials"][1]["source"], "result");
  // Recurrent at generation 1: {5.1, 4.5}: mean 4.8; at generation 2, recurrent-s6 alone.
  EXPECT_NEAR(s["arms"][1]["mean"][1].get<double>(), 4.8, 1e-12);
  EXPECT_EQ(s["arms"][1]["n"], nlohmann::json::array({2, 2, 1}));
  ASSERT_EQ(s["unreadable_results"].size(), 1u);
  EXPECT_NE(s["unreadable_results"][0].get<std::string>().find("recurrent-s10.results.json"), std::string::npos)
      << s["unreadable_results"];

  EXPECT_FALSE(w.poll());  // nothing new: no file read again
  // A result changes (a milestone extended it elsewhere): read again.
  write_result(r1 / "recurrent-s2.results.json", 2, {5.0, 5.1, 5.2}, 3);
  EXPECT_TRUE(w.poll());
  EXPECT_EQ(w.trials()[1].best_so_far, (std::vector<double>{5.0, 5.1, 5.2}));
  // Its log appears here (the trial runs again on this machine): the log is what is shown.
  write_trial(d / "recurrent-s2.lcmlog", {5.0}, 3);
  EXPECT_TRUE(w.poll());
  t = w.trials();
  EXPECT_EQ(t[1].name, "recurrent-s2");
  EXPECT_EQ(t[1].best_so_far, (std::vector<double>{5.0}));
  EXPECT_EQ(t[1].results_path, "");
  EXPECT_EQ(w.log_of("recurrent-s2"), d / "recurrent-s2.lcmlog");
  EXPECT_FALSE(w.poll());

  // A folder whose trials are all known from results is an experiment too.
  TempDir empty;
  ExperimentWatch only_results(empty.path, o);
  EXPECT_EQ(only_results.trials().size(), 3u);
}

TEST(ExperimentWatch, ALogCutBackWhenItsTrialResumesIsReadAgain) {
  TempDir d;
  const std::string log = d / "recurrent-s2.lcmlog";
  write_trial(d / "a.tmp", {5.0, 5.1, 5.2});  // read, then the trial stops during generation 3
  write_trial(d / "b.tmp", {5.0, 5.1});       // its checkpoint holds 0-1: the resume cuts 2
  write_trial(d / "c.tmp", {5.0, 5.1, 6.0, 6.5});
  const std::string a = bytes_of(d / "a.tmp"), b = bytes_of(d / "b.tmp"), c = bytes_of(d / "c.tmp");
  for (const char* f : {"a.tmp", "b.tmp", "c.tmp"}) fs::remove(d / f);
  put(log, a);
  ExperimentWatch w(d.path, ExperimentWatchOptions{});
  EXPECT_EQ(w.trials()[0].best_so_far, (std::vector<double>{5.0, 5.1, 5.2}));
  put(log, b);  // shorter than what was read
  EXPECT_TRUE(w.poll());
  EXPECT_EQ(w.trials()[0].best_so_far, (std::vector<double>{5.0, 5.1}));
  put(log, c);  // the resumed run goes on
  EXPECT_TRUE(w.poll());
  EXPECT_EQ(w.trials()[0].best_so_far, (std::vector<double>{5.0, 5.1, 6.0, 6.5}));
  // Rewritten under what was read, as long as before: read again too.
  write_trial(d / "d.tmp", {5.0, 5.1, 6.0, 7.5});
  const std::string e = bytes_of(d / "d.tmp");
  ASSERT_EQ(e.size(), c.size());
  put(log, e);
  EXPECT_TRUE(w.poll());
  EXPECT_EQ(w.trials()[0].best_so_far, (std::vector<double>{5.0, 5.1, 6.0, 7.5}));
  EXPECT_EQ(nlohmann::json::parse(w.summary())["unreadable_results"].size(), 0u);
}

TEST(ExperimentWatch, ALogContinuedFromAPortableCheckpointTakesItsEarlierGenerations) {
  TempDir d;
  // Generations 0-1 ran on another machine; this log continues at 2 (robozoo-experiment --checkpoints).
  write_result(d / "recurrent-s2.lcmlog.earlier.json", 2, {5.0, 5.1}, 4);
  write_trial(d / "recurrent-s2.lcmlog", {5.5, 6.0}, 4, 2);
  write_trial(d / "recurrent-s6.lcmlog", {4.0, 4.2, 4.4, 4.6}, 4);
  ExperimentWatch w(d.path, ExperimentWatchOptions{});
  const std::vector<TrialProgress> t = w.trials();
  ASSERT_EQ(t.size(), 2u);
  EXPECT_EQ(t[0].best_so_far, (std::vector<double>{5.0, 5.1, 5.5, 6.0}));
  EXPECT_EQ(t[0].state, "finished");
  nlohmann::json s = nlohmann::json::parse(w.summary());
  // Every generation has both trials: no gap in the arm's curve.
  EXPECT_EQ(s["arms"][0]["n"], nlohmann::json::array({2, 2, 2, 2}));
  EXPECT_NEAR(s["arms"][0]["mean"][0].get<double>(), 4.5, 1e-12);

  // An earlier result that does not read: the trial is listed unreadable, and the watch goes on.
  std::ofstream(d / "recurrent-s10.lcmlog.earlier.json") << "{";
  write_trial(d / "recurrent-s10.lcmlog", {3.0}, 4, 2);
  EXPECT_TRUE(w.poll());
  s = nlohmann::json::parse(w.summary());
  ASSERT_EQ(s["unreadable_results"].size(), 1u);
  EXPECT_NE(s["unreadable_results"][0].get<std::string>().find("recurrent-s10.lcmlog.earlier.json"), std::string::npos)
      << s["unreadable_results"];
}

TEST(ExperimentWatch, AGenerationNumberBeyondTheRunIsDamageNotASize) {
  TempDir d, r;
  // A log whose last generation message says 2,000,000,000 in a run of 5: not shown, nothing allocated.
  write_trial(d / "recurrent-s2.lcmlog", {5.0, 5.1}, 5);
  {
    const std::string log = d / "recurrent-s2.lcmlog";
    EventLogWriter w = EventLogWriter::resume(log, static_cast<int64_t>(fs::file_size(log)), 3);
    generation_t m = generation_message("t", 2000000000, 1);
    append(w, kChannelGeneration, m);
  }
  // A compact result whose generation is beyond its run's: listed unreadable.
  RunResults bad;
  {
    write_result(r / "recurrent-s6.results.json", 6, {4.0, 4.5}, 2);
    bad = read_run_results(r / "recurrent-s6.results.json");
    bad.run.generations[1].generation = 2000000000;
    write_run_results(r / "recurrent-s6.results.json", bad);
  }
  ExperimentWatchOptions o;
  o.results_dirs = {r.path};
  ExperimentWatch w(d.path, o);
  const std::vector<TrialProgress> t = w.trials();
  ASSERT_EQ(t.size(), 1u);
  EXPECT_EQ(t[0].best_so_far, (std::vector<double>{5.0, 5.1}));
  const nlohmann::json s = nlohmann::json::parse(w.summary());
  ASSERT_EQ(s["unreadable_results"].size(), 1u);
  EXPECT_NE(s["unreadable_results"][0].get<std::string>().find("recurrent-s6.results.json"), std::string::npos)
      << s["unreadable_results"];
  EXPECT_FALSE(w.poll());  // listed once: not news again at every poll
}

TEST(ExperimentWatch, AFolderWithoutAnExperimentIsRefused) {
  TempDir d;
  std::ofstream(d / "feedforward.lcmlog") << "x";
  try {
    ExperimentWatch w(d.path);
    FAIL() << "no experiment, yet watched";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("no experiment here"), std::string::npos) << e.what();
  }
  EXPECT_THROW(ExperimentWatch(d / "feedforward.lcmlog"), std::runtime_error);
  EXPECT_THROW(ExperimentWatch(d / "missing"), std::runtime_error);
  const robozoo::testing::Outcome o =
      robozoo::testing::run_shell(robozoo::testing::bin("robozoo-view") + " --experiment " + d.path);
  EXPECT_NE(o.status, 0);
  EXPECT_NE(o.output.find("no experiment here"), std::string::npos) << o.output;
  EXPECT_EQ(std::count(o.output.begin(), o.output.end(), '\n'), 1) << o.output;
  // --results must be a folder, and is for --experiment only.
  const robozoo::testing::Outcome missing = robozoo::testing::run_shell(
      robozoo::testing::bin("robozoo-view") + " --experiment " + d.path + " --results " + (d / "none"));
  EXPECT_EQ(missing.status, 2) << missing.output;
  EXPECT_NE(missing.output.find("--results " + (d / "none") + ": not a folder"), std::string::npos) << missing.output;
  const robozoo::testing::Outcome stray = robozoo::testing::run_shell(
      robozoo::testing::bin("robozoo-view") + " " + (d / "feedforward.lcmlog") + " --results " + d.path);
  EXPECT_EQ(stray.status, 2) << stray.output;
  EXPECT_NE(stray.output.find("are for --experiment"), std::string::npos) << stray.output;
}

}  // namespace
}  // namespace robozoo::view
