#include "runlog/read/log_index.hpp"

#include <gtest/gtest.h>

#include "evolve/messages/build.hpp"

namespace robozoo {
namespace {

struct LogBuilder {
  LogContents log;
  template <class T>
  LogBuilder& add(const std::string& channel, const T& m) {
    return raw(channel, encode_message(m));
  }
  LogBuilder& raw(const std::string& channel, std::vector<uint8_t> data) {
    LogRecord r;
    r.eventnum = static_cast<int64_t>(log.records.size());
    r.timestamp = 1000 * r.eventnum;
    r.channel = channel;
    r.data = std::move(data);
    log.records.push_back(std::move(r));
    return *this;
  }
};

run_t run(const std::string& id) {
  run_t m{};
  m.run_id = id;
  m.software_version = "x";
  m.config_json = "{}";
  return m;
}
generation_t generation(const std::string& run, int g, int64_t champion) {
  generation_t m{};
  m.run_id = run;
  m.generation = g;
  m.champion_id = champion;
  return m;
}
cppn_genome_t genome(const std::string& run, int g, int64_t id) {
  cppn_genome_t m{};
  m.run_id = run;
  m.generation = g;
  m.genome_id = id;
  return m;
}
morphology_t morphology(const std::string& run, int g, int64_t id) {
  morphology_t m{};
  m.run_id = run;
  m.generation = g;
  m.genome_id = id;
  return m;
}
pose_t pose(const std::string& run, int g, int64_t id, int step) {
  pose_t m{};
  m.run_id = run;
  m.generation = g;
  m.genome_id = id;
  m.step = step;
  m.sim_time = 0.01 * step;
  return m;
}

TEST(LogIndex, GroupsMorphologyAndPosesUnderTheirGenomeAndMarksChampions) {
  LogBuilder b;
  b.raw("LCM_SELF_TEST", {1, 2, 3})
      .add(kChannelRun, run("r"))
      .add(kChannelGeneration, generation("r", 0, 5))
      .add(kChannelGenome, genome("r", 0, 5))
      .add(kChannelGenome, genome("r", 0, 6))  // --publish-all: not the champion
      .add(kChannelMorphology, morphology("r", 0, 6))
      .add(kChannelMorphology, morphology("r", 0, 5))
      .add(kChannelPose, pose("r", 0, 5, 0))
      .add(kChannelPose, pose("r", 0, 5, 4))
      .add(kChannelRun, run("r"))
      .add(kChannelGenome, genome("r", 1, 9));  // no generation_t logged for generation 1
  const LogIndex ix = index_log(b.log);
  EXPECT_TRUE(ix.problems.empty());
  EXPECT_EQ(ix.foreign_events, 1u);
  EXPECT_EQ(ix.events.size(), b.log.records.size());
  EXPECT_EQ(ix.events[0].kind, EventKind::Foreign);
  EXPECT_EQ(ix.run_events, (std::vector<size_t>{1, 9}));
  ASSERT_EQ(ix.genomes.size(), 3u);
  const LoggedGenome& g5 = ix.genomes[0];
  EXPECT_EQ(g5.genome_id, 5);
  EXPECT_TRUE(g5.champion);
  EXPECT_EQ(g5.run_event, 1);
  EXPECT_EQ(g5.morphology_event, 6);
  EXPECT_EQ(g5.pose_events, (std::vector<size_t>{7, 8}));
  EXPECT_EQ(ix.events[8].step, 4);
  EXPECT_DOUBLE_EQ(ix.events[8].sim_time, 0.04);
  EXPECT_FALSE(ix.genomes[1].champion);
  EXPECT_EQ(ix.genomes[1].morphology_event, 5);
  EXPECT_TRUE(ix.genomes[2].champion);
  EXPECT_EQ(ix.genomes[2].run_event, 9);
  EXPECT_EQ(ix.to_check(false).size(), 2u);
  EXPECT_EQ(ix.to_check(true).size(), 3u);
  EXPECT_EQ(ix.find_genome(6), &ix.genomes[1]);
  EXPECT_EQ(ix.find_genome(6, "other"), nullptr);
  EXPECT_EQ(ix.find_genome(77), nullptr);
}

TEST(LogIndex, UndecodableAndOrphanEventsAreProblemsNotCrashes) {
  LogBuilder b;
  std::vector<uint8_t> truncated = encode_message(genome("r", 0, 1));
  truncated.resize(truncated.size() - 3);
  b.add(kChannelRun, run("r"))
      .add(kChannelGenome, pose("r", 0, 1, 0))  // a pose on the genome channel: wrong fingerprint
      .raw(kChannelGenome, truncated)
      .add(kChannelPose, pose("r", 0, 1, 0))  // its genome never made it
      .add(kChannelMorphology, morphology("q", 0, 1))
      .raw(kChannelRun, {});
  const LogIndex ix = index_log(b.log);
  EXPECT_TRUE(ix.genomes.empty());
  ASSERT_EQ(ix.problems.size(), 5u);
  EXPECT_EQ(ix.problems[0].eventnum, 1);
  EXPECT_EQ(ix.problems[0].channel, kChannelGenome);
  EXPECT_NE(ix.problems[0].what.find("fingerprint"), std::string::npos) << ix.problems[0].what;
  EXPECT_EQ(ix.events[1].kind, EventKind::Undecodable);
  EXPECT_EQ(ix.events[2].kind, EventKind::Undecodable);
  EXPECT_NE(ix.problems[2].what.find("no genome message before it"), std::string::npos) << ix.problems[2].what;
  EXPECT_NE(ix.problems[3].what.find("run q"), std::string::npos) << ix.problems[3].what;
  EXPECT_EQ(ix.problems[4].eventnum, 5);
}

TEST(LogIndex, GenomeWithoutAnEarlierRunHasNoRunEvent) {
  LogBuilder b;
  b.add(kChannelGenome, genome("r", 0, 1)).add(kChannelRun, run("r"));
  const LogIndex ix = index_log(b.log);
  ASSERT_EQ(ix.genomes.size(), 1u);
  EXPECT_EQ(ix.genomes[0].run_event, -1);
}

TEST(LogIndex, KindsOfChannels) {
  EXPECT_EQ(kind_of_channel("ROBOZOO_POSE"), EventKind::Pose);
  EXPECT_EQ(kind_of_channel("ROBOZOO_RUN"), EventKind::Run);
  EXPECT_EQ(kind_of_channel("ROBOZOO_POSES"), EventKind::Foreign);
  EXPECT_EQ(kind_of_channel("LCM_SELF_TEST"), EventKind::Foreign);
}

}  // namespace
}  // namespace robozoo
