// The live checker fed the small run's messages directly (no bus): a clean run
// is all ok; a lost pose, trajectory or generation is bus loss, not divergence;
// a changed value, or a physics that only the checker sees, is divergence.
#include "replay/check/live_check.hpp"

#include <gtest/gtest.h>

#include "tests/replay/replay_fixtures.hpp"

namespace robozoo::replay {
namespace {

using namespace robozoo::testing;

struct Fed {
  LiveCheckSummary summary;
  std::vector<std::string> lines;
};

Fed feed(const std::vector<LogRecord>& records, LiveCheckOptions o = {}) {
  Fed f;
  LiveChecker c(o, [&](const std::string& line) { f.lines.push_back(line); });
  for (const auto& r : records) c.ingest(r.channel, r.data);
  c.finish();
  f.summary = c.summary();
  return f;
}

std::string all(const Fed& f) {
  std::string s;
  for (const auto& l : f.lines) s += l + "\n";
  return s + format_live_summary(f.summary);
}

TEST(LiveCheck, TheWholeRunArrivesAndAgrees) {
  const Fed f = feed(small_log().records);
  EXPECT_EQ(f.summary.exit_code(), 0) << all(f);
  ASSERT_EQ(f.summary.verdicts.size(), 4u) << all(f);
  for (const auto& v : f.summary.verdicts) {
    EXPECT_EQ(v.result.status, ChampionResult::Status::Ok) << all(f);
    EXPECT_TRUE(v.loss.empty()) << all(f);
  }
  // A line per champion, as it completes.
  int ok_lines = 0;
  for (const auto& l : f.lines) ok_lines += l.rfind("ok ", 0) == 0;
  EXPECT_EQ(ok_lines, 4) << all(f);
}

TEST(LiveCheck, ALostPoseIsBusLossNotDivergence) {
  std::vector<LogRecord> v = small_log().records;
  const int64_t pose = nth_on(small_log(), kChannelPose, 7);
  v.erase(v.begin() + pose);
  const Fed f = feed(v);
  EXPECT_EQ(f.summary.exit_code(), 2) << all(f);
  EXPECT_EQ(f.summary.count(ChampionResult::Status::Diverged), 0) << all(f);
  EXPECT_EQ(f.summary.champions_with_loss(), 1) << all(f);
  EXPECT_NE(all(f).find("1 of 101 poses of its trajectory never arrived"), std::string::npos) << all(f);
}

TEST(LiveCheck, ALostTrajectoryOrGenerationIsBusLoss) {
  std::vector<LogRecord> v;
  for (const auto& r : small_log().records)
    if (r.channel != kChannelPose) v.push_back(r);
  const Fed f = feed(v);
  EXPECT_EQ(f.summary.exit_code(), 2) << all(f);
  EXPECT_EQ(f.summary.count(ChampionResult::Status::Diverged), 0);
  EXPECT_NE(all(f).find("its trajectory never arrived"), std::string::npos) << all(f);

  std::vector<LogRecord> w;
  bool skipping = false;
  for (const auto& r : small_log().records) {
    if (r.channel == kChannelGeneration) {
      generation_t g = decode_as<generation_t>(r);
      skipping = g.generation == 1;
    }
    if (!skipping) w.push_back(r);
  }
  const Fed g = feed(w);
  EXPECT_EQ(g.summary.exit_code(), 2) << all(g);
  EXPECT_EQ(g.summary.count(ChampionResult::Status::Diverged), 0) << all(g);
  EXPECT_NE(all(g).find("generations 1 to 1 never arrived"), std::string::npos) << all(g);
}

TEST(LiveCheck, AChangedPoseIsDivergence) {
  std::vector<LogRecord> v = small_log().records;
  const int64_t at = nth_on(small_log(), kChannelPose, 9);
  pose_t p = decode_as<pose_t>(v[at]);
  p.body_position[0][2] = std::nextafter(p.body_position[0][2], 1e9);
  v[at].data = encode_message(p);
  const Fed f = feed(v);
  EXPECT_EQ(f.summary.exit_code(), 1) << all(f);
  EXPECT_EQ(f.summary.count(ChampionResult::Status::Diverged), 1) << all(f);
  EXPECT_NE(all(f).find("DIVERGED"), std::string::npos);
}

TEST(LiveCheck, APhysicsOnlyTheCheckerSeesIsDivergence) {
  LiveCheckOptions o;
  o.sets = {"sim.friction=0.5"};
  const Fed f = feed(small_log().records, o);
  EXPECT_EQ(f.summary.exit_code(), 1) << all(f);
  EXPECT_GE(f.summary.count(ChampionResult::Status::Diverged), 1) << all(f);
}

TEST(LiveCheck, ThePublishersCountRevealsLossBetweenChampions) {
  std::vector<LogRecord> v = small_log().records;
  size_t sent = 0;
  for (const auto& r : v) sent += r.channel.rfind("ROBOZOO_", 0) == 0;
  bus_status_t s{};
  s.run_id = "feedforward-s7";
  s.generation = 3;
  s.messages_published = static_cast<int64_t>(sent);
  LogRecord status;
  status.channel = kChannelBus;
  status.data = encode_message(s);
  v.push_back(status);
  EXPECT_EQ(feed(v).summary.exit_code(), 0) << all(feed(v));
  s.messages_published += 2;  // two that never arrived
  v.back().data = encode_message(s);
  const Fed f = feed(v);
  EXPECT_EQ(f.summary.exit_code(), 2) << all(f);
  ASSERT_EQ(f.summary.loss.size(), 1u) << all(f);
  EXPECT_NE(f.summary.loss[0].find("had sent " + std::to_string(sent + 2)), std::string::npos) << f.summary.loss[0];
}

TEST(LiveCheck, JoiningMidRunWaitsForTheNextRunMessage) {
  std::vector<LogRecord> v(small_log().records.begin() + nth_on(small_log(), kChannelGenome, 0),
                           small_log().records.end());
  const Fed f = feed(v);
  EXPECT_EQ(f.summary.exit_code(), 0) << all(f);
  EXPECT_EQ(f.summary.verdicts.size(), 3u) << all(f);
}

TEST(LiveCheck, NothingReceivedIsUnusable) {
  const Fed f = feed({});
  EXPECT_EQ(f.summary.exit_code(), 2);
  EXPECT_NE(format_live_summary(f.summary).find("no ROBOZOO_RUN arrived"), std::string::npos);
}

}  // namespace
}  // namespace robozoo::replay
