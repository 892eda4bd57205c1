#include "runlog/read/message_collector.hpp"

#include <gtest/gtest.h>

#include "tests/render/messages.hpp"

namespace robozoo {
namespace {

using namespace robozoo::render::testing;

struct Feed {
  MessageCollector c;
  std::vector<int64_t> champions, streams;
  explicit Feed(CollectorOptions o = {}) : c(o) {
    c.on_champion([this](const RunRecord&, const GenomeRecord& g) { champions.push_back(g.genome.genome_id); });
    c.on_stream_complete([this](const RunRecord&, GenomeRecord& g) { streams.push_back(g.genome.genome_id); });
  }
  template <class T>
  void send(const char* channel, const T& m) {
    const std::vector<uint8_t> b = encode_message(m);
    c.ingest(channel, b.data(), b.size(), "test");
  }
  void bytes(const char* channel, const std::vector<uint8_t>& b) { c.ingest(channel, b.data(), b.size(), "test"); }
};

// One generation as robozoo-evolve publishes it: RUN, GENERATION, the
// champion's GENOME and MORPHOLOGY, then its pose stream.
void generation(Feed& f, const std::string& id, int32_t g, int64_t genome, std::vector<int32_t> steps) {
  f.send(kChannelRun, run_message(id));
  f.send(kChannelGeneration, generation_message(id, g, genome));
  f.send(kChannelGenome, genome_message(id, g, genome, 15.0 + g));
  f.send(kChannelMorphology, morphology_message(id, g, genome));
  for (int32_t s : steps) f.send(kChannelPose, pose_message(id, g, genome, s, 0.001 * s));
}

TEST(MessageCollector, GathersARun) {
  Feed f;
  generation(f, "r", 0, 10, {0, 50, 100});
  generation(f, "r", 1, 11, {});
  ASSERT_EQ(f.c.runs().size(), 1u);
  const RunRecord& run = *f.c.runs()[0];
  EXPECT_EQ(run.run.run_id, "r");
  EXPECT_EQ(run.source, "test");
  EXPECT_EQ(run.generations.size(), 2u);
  ASSERT_EQ(run.genomes.size(), 2u);
  EXPECT_EQ(run.find(10)->poses.size(), 3u);
  EXPECT_EQ(run.find(10)->stream, GenomeRecord::Stream::Complete);  // its last step reached run_t.steps
  EXPECT_EQ(f.champions, (std::vector<int64_t>{10, 11}));
  EXPECT_EQ(f.streams, (std::vector<int64_t>{10}));
  EXPECT_EQ(f.c.stats().rejected(), 0);
  EXPECT_EQ(f.c.stats().accepted, f.c.stats().messages);
}

TEST(MessageCollector, JoinsAtTheNextRunMessage) {
  Feed f;
  // Joined mid-generation: a genome, its morphology and half a pose stream.
  f.send(kChannelGenome, genome_message("r", 3, 30, 18.0));
  f.send(kChannelMorphology, morphology_message("r", 3, 30));
  f.send(kChannelPose, pose_message("r", 3, 30, 40));
  EXPECT_TRUE(f.c.runs().empty());
  EXPECT_EQ(f.c.stats().before_run, 3);
  EXPECT_EQ(f.c.stats().rejected(), 0);  // waiting is not an error
  generation(f, "r", 4, 40, {0, 100});
  ASSERT_EQ(f.c.runs().size(), 1u);
  EXPECT_EQ(f.c.runs()[0]->genomes.size(), 1u);
  EXPECT_EQ(f.champions, (std::vector<int64_t>{40}));
  EXPECT_EQ(f.streams, (std::vector<int64_t>{40}));
}

TEST(MessageCollector, CorruptMessagesAreCountedAndSkipped) {
  Feed f;
  generation(f, "r", 0, 10, {});
  std::vector<uint8_t> pose = encode_message(pose_message("r", 0, 10, 0));
  f.bytes(kChannelPose, std::vector<uint8_t>(pose.begin(), pose.begin() + static_cast<long>(pose.size() / 2)));
  f.bytes(kChannelMorphology, {1, 2, 3, 4, 5, 6, 7, 8, 9});
  f.bytes(kChannelRun, {});
  std::vector<uint8_t> huge = pose;
  huge[huge.size() - 8] = 0x7f;  // num_neurons: a count that runs past the end
  f.bytes(kChannelPose, huge);
  const CollectorStats& s = f.c.stats();
  EXPECT_GE(s.undecodable, 3);
  EXPECT_EQ(s.rejected(), s.undecodable + s.inconsistent + s.orphans);
  EXPECT_GE(s.rejected(), 4);
  EXPECT_FALSE(s.problems.empty());
  EXPECT_TRUE(f.c.runs()[0]->find(10)->poses.empty());
  // Still works afterwards.
  f.send(kChannelPose, pose_message("r", 0, 10, 0));
  EXPECT_EQ(f.c.runs()[0]->find(10)->poses.size(), 1u);
}

TEST(MessageCollector, SizesThatDoNotAddUpAreRejected) {
  Feed f;
  generation(f, "r", 0, 10, {0});
  f.send(kChannelPose, pose_message("r", 0, 10, 4, 0.0, 3));  // 3 spheres, the robot has 4
  morphology_t bad = morphology_message("r", 0, 11);
  bad.spheres[1].body = 7;  // no such body
  f.send(kChannelGenome, genome_message("r", 0, 11, 1.0));
  f.send(kChannelMorphology, bad);
  f.send(kChannelPose, pose_message("r", 0, 99, 0));  // genome never seen
  f.send(kChannelPose, pose_message("r", 0, 10, 0));  // step going back
  const CollectorStats& s = f.c.stats();
  EXPECT_EQ(s.inconsistent, 3);
  EXPECT_EQ(s.orphans, 1);
  EXPECT_FALSE(f.c.runs()[0]->find(11)->has_morphology);
  EXPECT_EQ(f.c.runs()[0]->find(10)->poses.size(), 1u);
}

TEST(MessageCollector, StreamsEndingEarlyCompleteOnTheNextMessageOrOnClose) {
  Feed f;
  generation(f, "r", 0, 10, {0, 20, 37});  // stopped early at step 37
  EXPECT_TRUE(f.streams.empty());
  EXPECT_TRUE(f.c.has_open_stream());
  f.send(kChannelRun, run_message("r"));
  EXPECT_EQ(f.streams, (std::vector<int64_t>{10}));
  generation(f, "r", 1, 11, {0, 20});
  EXPECT_TRUE(f.c.has_open_stream());
  f.c.close_open_streams();
  EXPECT_EQ(f.streams, (std::vector<int64_t>{10, 11}));
  EXPECT_FALSE(f.c.has_open_stream());
  f.send(kChannelPose, pose_message("r", 1, 11, 30));  // after its end
  EXPECT_EQ(f.c.stats().inconsistent, 1);
}

TEST(MessageCollector, NonChampionsGetNoPicture) {
  Feed f;
  f.send(kChannelRun, run_message("r"));
  f.send(kChannelGeneration, generation_message("r", 0, 10));
  f.send(kChannelGenome, genome_message("r", 0, 10, 2.0));
  f.send(kChannelMorphology, morphology_message("r", 0, 10));
  f.send(kChannelGenome, genome_message("r", 0, 12, 1.0));  // --publish-all
  f.send(kChannelMorphology, morphology_message("r", 0, 12));
  EXPECT_EQ(f.champions, (std::vector<int64_t>{10}));
  EXPECT_FALSE(f.c.runs()[0]->find(12)->champion);
}

TEST(MessageCollector, AThrowingCallbackIsContained) {
  MessageCollector c;
  c.on_champion([](const RunRecord&, const GenomeRecord&) { throw std::runtime_error("boom"); });
  auto send = [&](const char* ch, const auto& m) {
    const auto b = encode_message(m);
    c.ingest(ch, b.data(), b.size());
  };
  send(kChannelRun, run_message("r"));
  send(kChannelGenome, genome_message("r", 0, 1, 1.0));
  EXPECT_NO_THROW(send(kChannelMorphology, morphology_message("r", 0, 1)));
  EXPECT_EQ(c.stats().inconsistent, 1);
  EXPECT_NE(c.stats().problems.back().find("boom"), std::string::npos);
}

TEST(MessageCollector, PosesCanBeCountedWithoutKeepingThem) {
  CollectorOptions o;
  o.keep_poses = false;
  Feed f(o);
  generation(f, "r", 0, 10, {0, 50, 100});
  EXPECT_TRUE(f.c.runs()[0]->find(10)->poses.empty());
  EXPECT_EQ(f.c.runs()[0]->find(10)->pose_count, 3);
  EXPECT_EQ(f.streams, (std::vector<int64_t>{10}));
}

TEST(MessageCollector, OtherChannelsAreIgnored) {
  Feed f;
  f.bytes("LCM_SELF_TEST", {1, 2, 3});
  EXPECT_EQ(f.c.stats().other_channels, 1);
  EXPECT_EQ(f.c.stats().rejected(), 0);
}

}  // namespace
}  // namespace robozoo
