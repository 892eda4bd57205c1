// The whole log proved message by message: a log from a real short run checks
// clean, and each way of changing it while keeping the event numbering
// consistent (EventLogWriter renumbers the copy) is a divergence that names the
// event, channel, field and both values.
#include "replay/log/log_structure.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "replay/check/check.hpp"
#include "tests/replay/replay_fixtures.hpp"

namespace robozoo::replay {
namespace {

using namespace robozoo::testing;

/// Record indices of the poses of the n-th logged trajectory (0-based).
std::vector<size_t> trajectory_records(size_t n) {
  std::vector<std::vector<size_t>> runs;
  int64_t genome = -1;
  const auto& recs = small_log().records;
  for (size_t i = 0; i < recs.size(); ++i) {
    if (recs[i].channel != kChannelPose) continue;
    const pose_t p = decode_as<pose_t>(recs[i]);
    if (runs.empty() || p.genome_id != genome) runs.emplace_back();
    genome = p.genome_id;
    runs.back().push_back(i);
  }
  return n < runs.size() ? runs[n] : std::vector<size_t>{};
}

/// The log written again with `edit` applied to the record list.
CheckReport check_edited(const std::function<void(std::vector<LogRecord>&)>& edit) {
  TempDir dir;
  LogContents log = small_log();
  edit(log.records);
  write_log(log, dir / "edited.lcmlog");
  return check_log_file(dir / "edited.lcmlog", {});
}

/// The first champion that diverged, or nullptr.
const ChampionResult* first_diverged(const CheckReport& r) {
  for (const auto& c : r.champions)
    if (c.status == ChampionResult::Status::Diverged) return &c;
  return nullptr;
}

TEST(LogStructure, TheRealLogIsProvedClean) {
  const CheckReport r = check_log_file(small_run_log(), {});
  EXPECT_EQ(r.exit_code(), 0) << format_text(r);
  EXPECT_TRUE(r.structure.empty());
  EXPECT_EQ(r.generations_proved, 4);
  ASSERT_FALSE(trajectory_records(0).empty()) << "the small run must log a trajectory";
  ASSERT_FALSE(trajectory_records(1).empty()) << "the small run must log two trajectories";
  for (const auto& c : r.champions) {
    if (c.poses_logged > 0) {
      EXPECT_EQ(c.poses_logged, c.poses_expected) << champion_line(c, false);
    }
  }
}

TEST(LogStructure, ADeletedPoseIsNamed) {
  const auto t = trajectory_records(0);
  const pose_t gone = decode_as<pose_t>(small_log().records[t[5]]);
  const pose_t next = decode_as<pose_t>(small_log().records[t[6]]);
  const CheckReport r = check_edited([&](std::vector<LogRecord>& v) { v.erase(v.begin() + t[5]); });
  EXPECT_EQ(r.exit_code(), 1) << format_text(r);
  const ChampionResult* c = first_diverged(r);
  ASSERT_NE(c, nullptr) << format_text(r);
  EXPECT_EQ(c->genome_id, gone.genome_id);
  const Mismatch& m = c->mismatches.at(0);
  EXPECT_EQ(m.what, "trajectory");
  EXPECT_NE(m.field.find("pose 5"), std::string::npos) << m.field;
  EXPECT_EQ(m.logged, std::to_string(next.step));
  EXPECT_EQ(m.recomputed, std::to_string(gone.step));
}

TEST(LogStructure, ADuplicatedPoseIsNamed) {
  const auto t = trajectory_records(0);
  const pose_t dup = decode_as<pose_t>(small_log().records[t[5]]);
  const pose_t next = decode_as<pose_t>(small_log().records[t[6]]);
  const CheckReport r = check_edited([&](std::vector<LogRecord>& v) { v.insert(v.begin() + t[5], v[t[5]]); });
  EXPECT_EQ(r.exit_code(), 1) << format_text(r);
  const ChampionResult* c = first_diverged(r);
  ASSERT_NE(c, nullptr) << format_text(r);
  const Mismatch& m = c->mismatches.at(0);
  EXPECT_NE(m.field.find("pose 6"), std::string::npos) << m.field;
  EXPECT_EQ(m.logged, std::to_string(dup.step));
  EXPECT_EQ(m.recomputed, std::to_string(next.step));
}

TEST(LogStructure, TwoSwappedPosesAreNamed) {
  const auto t = trajectory_records(1);
  const pose_t a = decode_as<pose_t>(small_log().records[t[7]]);
  const pose_t b = decode_as<pose_t>(small_log().records[t[8]]);
  const CheckReport r = check_edited([&](std::vector<LogRecord>& v) { std::swap(v[t[7]], v[t[8]]); });
  EXPECT_EQ(r.exit_code(), 1) << format_text(r);
  const ChampionResult* c = first_diverged(r);
  ASSERT_NE(c, nullptr) << format_text(r);
  EXPECT_EQ(c->genome_id, a.genome_id);
  const Mismatch& m = c->mismatches.at(0);
  EXPECT_NE(m.field.find("pose 7"), std::string::npos) << m.field;
  EXPECT_EQ(m.logged, std::to_string(b.step));
  EXPECT_EQ(m.recomputed, std::to_string(a.step));
  // Each pose's values still agree with the state at its own step.
  EXPECT_EQ(c->poses_diverged, 0);
}

void expect_missing_trajectory(size_t which) {
  const auto t = trajectory_records(which);
  const pose_t p = decode_as<pose_t>(small_log().records[t[0]]);
  const CheckReport r =
      check_edited([&](std::vector<LogRecord>& v) { v.erase(v.begin() + t.front(), v.begin() + t.back() + 1); });
  EXPECT_EQ(r.exit_code(), 1) << format_text(r);
  ASSERT_FALSE(r.structure.empty()) << format_text(r);
  const LogDifference& d = r.structure[0];
  EXPECT_EQ(d.channel, kChannelPose);
  EXPECT_EQ(d.generation, p.generation);
  EXPECT_EQ(d.field, "poses of champion " + std::to_string(p.genome_id));
  EXPECT_EQ(d.logged, "none");
  EXPECT_NE(format_text(r).find("DIVERGED event"), std::string::npos);
}

TEST(LogStructure, AChampionsWholeTrajectoryRemovedIsNamed) { expect_missing_trajectory(0); }

TEST(LogStructure, TheLastGenerationsTrajectoryRemovedIsNamed) {
  // The run is finished, so the end of the log is no excuse.
  expect_missing_trajectory(1);
}

TEST(LogStructure, ARemovedGenerationMessageIsNamed) {
  const size_t g = static_cast<size_t>(nth_on(small_log(), kChannelGeneration, 2));
  const generation_t removed = decode_as<generation_t>(small_log().records[g]);
  const int64_t genome_event = small_log().records[g + 1].eventnum - 1;  // renumbered: one earlier
  const CheckReport r = check_edited([&](std::vector<LogRecord>& v) { v.erase(v.begin() + g); });
  EXPECT_EQ(r.exit_code(), 1) << format_text(r);
  ASSERT_FALSE(r.structure.empty());
  const LogDifference& d = r.structure[0];
  EXPECT_EQ(d.eventnum, genome_event);
  EXPECT_EQ(d.channel, kChannelGenome);
  EXPECT_EQ(d.generation, removed.generation);
  EXPECT_EQ(d.logged, kChannelGenome);
  EXPECT_EQ(d.expected, kChannelGeneration);
  // The next generation_t is then numbered one too far.
  bool numbered = false;
  for (const auto& x : r.structure)
    numbered = numbered || (x.field == "generation" && x.logged == std::to_string(removed.generation + 1) &&
                            x.expected == std::to_string(removed.generation));
  EXPECT_TRUE(numbered) << format_text(r);
}

/// The small log with one field of the n-th generation_t changed.
CheckReport with_generation(size_t n, const std::function<void(generation_t&)>& change,
                            generation_t* before = nullptr) {
  const size_t g = static_cast<size_t>(nth_on(small_log(), kChannelGeneration, n));
  if (before) *before = decode_as<generation_t>(small_log().records[g]);
  return check_edited([&](std::vector<LogRecord>& v) {
    generation_t m = decode_as<generation_t>(v[g]);
    change(m);
    v[g].data = encode_message(m);
  });
}

TEST(LogStructure, AChangedBestFitnessIsNamedWithBothValues) {
  generation_t was{};
  const CheckReport r = with_generation(
      1, [](generation_t& m) { m.best_fitness += 0.25; }, &was);
  EXPECT_EQ(r.exit_code(), 1) << format_text(r);
  ASSERT_FALSE(r.structure.empty());
  const int64_t event = small_log().records[nth_on(small_log(), kChannelGeneration, 1)].eventnum;
  EXPECT_EQ(r.structure[0].eventnum, event);  // the first difference is at that message
  const auto it = std::find_if(r.structure.begin(), r.structure.end(),
                               [](const LogDifference& x) { return x.field == "best_fitness"; });
  ASSERT_NE(it, r.structure.end()) << format_text(r);
  const LogDifference& d = *it;
  EXPECT_EQ(d.channel, kChannelGeneration);
  EXPECT_EQ(d.eventnum, event);
  EXPECT_EQ(d.logged, exact_text(was.best_fitness + 0.25));
  EXPECT_EQ(d.expected, exact_text(was.best_fitness));
  for (const auto& c : r.champions) EXPECT_EQ(c.status, ChampionResult::Status::Ok);
}

TEST(LogStructure, EvaluationsMustBeCumulative) {
  generation_t was{};
  const CheckReport r = with_generation(
      2, [](generation_t& m) { m.evaluations += 1; }, &was);
  EXPECT_EQ(r.exit_code(), 1) << format_text(r);
  ASSERT_FALSE(r.structure.empty());
  EXPECT_EQ(r.structure[0].field, "evaluations");
  EXPECT_EQ(r.structure[0].logged, std::to_string(was.evaluations + 1));
  EXPECT_EQ(r.structure[0].expected, std::to_string(3 * 24));  // three generations of 24
}

TEST(LogStructure, OutcomeCountsMustAddUpToThePopulation) {
  const CheckReport r = with_generation(0, [](generation_t& m) { m.n_completed += 1; });
  EXPECT_EQ(r.exit_code(), 1) << format_text(r);
  ASSERT_FALSE(r.structure.empty());
  EXPECT_EQ(r.structure[0].field, "outcome counts");
  EXPECT_EQ(r.structure[0].logged, "25");
  EXPECT_EQ(r.structure[0].expected, "24");
}

TEST(LogStructure, BestSoFarIsTheRunningMaximum) {
  const CheckReport r = with_generation(3, [](generation_t& m) { m.best_so_far_fitness = 1000.0; });
  EXPECT_EQ(r.exit_code(), 1) << format_text(r);
  ASSERT_FALSE(r.structure.empty());
  EXPECT_EQ(r.structure[0].field, "best_so_far_fitness");
  EXPECT_EQ(r.structure[0].logged, "1000");
}

TEST(LogStructure, AChangedChampionIdIsNamed) {
  generation_t was{};
  const CheckReport r = with_generation(
      1, [](generation_t& m) { m.champion_id += 1; }, &was);
  EXPECT_EQ(r.exit_code(), 1) << format_text(r);
  ASSERT_FALSE(r.structure.empty());
  EXPECT_EQ(r.structure[0].field, "champion_id");
  EXPECT_EQ(r.structure[0].logged, std::to_string(was.champion_id + 1));
  EXPECT_EQ(r.structure[0].expected, std::to_string(was.champion_id));
}

TEST(LogStructure, TheRunMessageComesFirstAndOncePerGeneration) {
  const size_t first_run = static_cast<size_t>(nth_on(small_log(), kChannelRun, 0));
  const size_t second_run = static_cast<size_t>(nth_on(small_log(), kChannelRun, 1));
  ASSERT_EQ(first_run, 0u);
  // Moved after the first generation_t: the run's first message is not its run_t.
  const CheckReport moved = check_edited([&](std::vector<LogRecord>& v) { std::swap(v[0], v[1]); });
  EXPECT_EQ(moved.exit_code(), 1) << format_text(moved);
  ASSERT_FALSE(moved.structure.empty());
  EXPECT_EQ(moved.structure[0].field, "channel");
  EXPECT_EQ(moved.structure[0].logged, kChannelGeneration);
  EXPECT_EQ(moved.structure[0].expected, kChannelRun);
  // Twice before one generation.
  const CheckReport twice =
      check_edited([&](std::vector<LogRecord>& v) { v.insert(v.begin() + second_run, v[second_run]); });
  EXPECT_EQ(twice.exit_code(), 1) << format_text(twice);
  ASSERT_FALSE(twice.structure.empty());
  EXPECT_EQ(twice.structure[0].channel, kChannelRun);
  EXPECT_EQ(twice.structure[0].expected, kChannelGeneration);
  // A repeat that differs from the first.
  const CheckReport seed = check_edited([&](std::vector<LogRecord>& v) {
    run_t m = decode_as<run_t>(v[second_run]);
    m.seed += 1;
    v[second_run].data = encode_message(m);
  });
  EXPECT_EQ(seed.exit_code(), 1) << format_text(seed);
  ASSERT_FALSE(seed.structure.empty());
  EXPECT_EQ(seed.structure[0].field, "seed");
  EXPECT_EQ(seed.structure[0].logged, "8");
  EXPECT_EQ(seed.structure[0].expected, "7");
}

TEST(LogStructure, AMorphologyBeforeItsGenomeIsNamed) {
  const size_t g = static_cast<size_t>(nth_on(small_log(), kChannelGenome, 1));
  ASSERT_EQ(small_log().records[g + 1].channel, kChannelMorphology);
  const CheckReport r = check_edited([&](std::vector<LogRecord>& v) { std::swap(v[g], v[g + 1]); });
  EXPECT_EQ(r.exit_code(), 1) << format_text(r);
  ASSERT_FALSE(r.structure.empty());
  EXPECT_EQ(r.structure[0].channel, kChannelMorphology);
}

TEST(LogStructure, ALogCutInsideAGenerationOfAnUnfinishedRunIsIncompleteInput) {
  // The log of a run still being written: the last generation's trajectory is
  // half there. Not a divergence: what is there is checked and agrees.
  const auto t = trajectory_records(1);
  TempDir dir;
  LogContents log = small_log();
  log.records.resize(t[t.size() / 2]);
  for (auto& rec : log.records) {
    if (rec.channel != kChannelRun) continue;
    run_t m = decode_as<run_t>(rec);
    m.generations = 10;  // the run goes on
    nlohmann::json j = nlohmann::json::parse(m.config_json);
    j["generations"] = 10;
    m.config_json = j.dump();
    rec.data = encode_message(m);
  }
  write_log(log, dir / "growing.lcmlog");
  const CheckReport r = check_log_file(dir / "growing.lcmlog", {});
  EXPECT_EQ(r.exit_code(), 0) << format_text(r);
  EXPECT_TRUE(r.structure.empty()) << format_text(r);
  for (const auto& c : r.champions) EXPECT_EQ(c.status, ChampionResult::Status::Ok) << champion_line(c, false);
  ASSERT_FALSE(r.champions.empty());
  EXPECT_EQ(r.champions.back().poses_logged, static_cast<int64_t>(t.size() / 2));
  EXPECT_EQ(r.champions.back().poses_expected, static_cast<int64_t>(t.size()));
  // The same cut in the finished run is a divergence: its trajectory must be whole.
  TempDir dir2;
  LogContents cut = small_log();
  cut.records.resize(t[t.size() / 2]);
  write_log(cut, dir2 / "cut.lcmlog");
  EXPECT_EQ(check_log_file(dir2 / "cut.lcmlog", {}).exit_code(), 1);
}

}  // namespace
}  // namespace robozoo::replay
