#include "evolve/record/run_summary.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "runlog/read/log_reader.hpp"
#include "study/analysis/read/log_results.hpp"
#include "tests/study/analysis/hand_made_log.hpp"
#include "tests/support/subprocess.hpp"

namespace robozoo {
namespace {

using namespace robozoo::testing;

HandRun three_generations() {
  HandRun run;
  run.regime = 1;
  run.seed = 4;
  run.population = 20;
  run.generations_requested = 3;
  const std::vector<NodeSpec> nodes = {{0, 0, 0}, {9, 2, 0}};
  run.generations = {
      {4.0, 4.0, 0, 10, {-1}, {}, nodes, {{0, 9}}, std::nullopt},
      {15.5, 15.5, 1, 11, {-1, 0, 1}, {0.1, 0.2, 0.3}, nodes, {{0, 9}}, std::vector<double>{0.1, 0.25, 0.5}},
      {15.5, 15.5, 1, 12, {-1, 0, 1}, {0.1, 0.2, 0.3}, nodes, {{0, 9}}, std::nullopt},
  };
  return run;
}

TEST(RunSummary, ReadsTheRunTheGenerationsAndTheChampions) {
  TempDir dir;
  write_hand_log(dir / "r.lcmlog", three_generations());
  const RunSummary s = summarize_run_file(dir / "r.lcmlog");
  EXPECT_EQ(s.run_id, "recurrent-s4");
  EXPECT_EQ(s.regime, 1);
  EXPECT_EQ(s.seed, 4);
  EXPECT_EQ(s.population, 20);
  EXPECT_EQ(s.generations_requested, 3);
  ASSERT_EQ(s.generations.size(), 3u);
  EXPECT_TRUE(s.complete());
  EXPECT_EQ(s.generations[1].best_fitness, 15.5);
  EXPECT_EQ(s.generations[2].champion_id, 12);
  // The other genome of each generation is not taken for the champion.
  ASSERT_EQ(s.champions.size(), 3u);
  for (int g = 0; g < 3; ++g) {
    EXPECT_EQ(s.champions[g].genome.genome_id, 10 + g);
    EXPECT_TRUE(s.champions[g].has_morphology);
  }
  EXPECT_EQ(s.champions[1].morphology.spheres.size(), 3u);
  // The pose stream's lowest heights (three poses, the middle one lowest).
  ASSERT_EQ(s.min_center_z.count(11), 1u);
  EXPECT_EQ(s.min_center_z.at(11), (std::vector<double>{0.1, 0.25, 0.5}));
  EXPECT_EQ(s.undecodable, 0);
  // Best of run: the highest fitness, the earliest among equals (the one with poses).
  ASSERT_NE(best_of_run(s), nullptr);
  EXPECT_EQ(best_of_run(s)->genome.genome_id, 11);
}

TEST(RunSummary, AnUnfinishedRunIsNotComplete) {
  TempDir dir;
  HandRun run = three_generations();
  run.generations_requested = 5;
  write_hand_log(dir / "r.lcmlog", run);
  EXPECT_FALSE(summarize_run_file(dir / "r.lcmlog").complete());
}

TEST(RunSummary, CorruptMessagesAreCountedNotTrusted) {
  TempDir dir;
  const std::string path = dir / "r.lcmlog";
  write_hand_log(path, three_generations());
  LogContents log = read_event_log(path);
  // Break the first genome message's node count: safe_decode must refuse it.
  for (auto& r : log.records)
    if (r.channel == kChannelGenome) {
      r.data.resize(r.data.size() / 2);
      break;
    }
  const RunSummary s = summarize_run(log, path);
  EXPECT_EQ(s.undecodable, 1);
  EXPECT_EQ(s.generations.size(), 3u);
}

// The file is read by runlog's reader: garbage in the middle of a log (a
// damaged disk block) hides no event after it, and a cut last event is reported.
TEST(RunSummary, ReadsPastGarbageAndReportsACutLastEvent) {
  TempDir dir;
  const std::string path = dir / "r.lcmlog";
  write_hand_log(path, three_generations());
  const ScannedLog clean = scan_event_log(path);
  size_t last_generation = clean.contents.records.size();
  for (size_t i = 0; i < clean.contents.records.size(); ++i)
    if (clean.contents.records[i].channel == kChannelGeneration) last_generation = i;
  ASSERT_LT(last_generation, clean.contents.records.size());
  std::ifstream in(path, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  in.close();
  bytes.insert(static_cast<size_t>(clean.offsets[last_generation]), "garbage");
  bytes.resize(bytes.size() - 3);  // and cut the last event
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
  const RunSummary s = summarize_run_file(path);
  ASSERT_EQ(s.generations.size(), 3u);
  EXPECT_EQ(s.generations[2].champion_id, 12);
  EXPECT_TRUE(s.truncated);
}

TEST(RunSummary, ALogWithoutARunIsRefused) {
  TempDir dir;
  const std::string path = dir / "empty.lcmlog";
  EventLogWriter::create(path).sync();
  EXPECT_THROW(summarize_run_file(path), std::invalid_argument);
  EXPECT_THROW(summarize_run_file(dir / "missing.lcmlog"), std::runtime_error);
}

}  // namespace
}  // namespace robozoo
