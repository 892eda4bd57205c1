#include "view/state/view_state.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "tests/render/messages.hpp"

namespace robozoo::view {
namespace {

using namespace robozoo::render::testing;

template <class T>
void send(ViewState& s, const char* channel, const T& m) {
  const std::vector<uint8_t> b = encode_message(m);
  s.ingest(channel, b.data(), b.size());
}

std::vector<nlohmann::json> drain(Client& c) {
  std::vector<nlohmann::json> out;
  while (auto f = c.queue.pop()) out.push_back(nlohmann::json::parse(**f));
  return out;
}

std::vector<std::string> kinds(const std::vector<nlohmann::json>& frames) {
  std::vector<std::string> k;
  for (const auto& f : frames) k.push_back(f["t"]);
  return k;
}

/// Generation g of run "r": champion 10+g, its genome and morphology and, with
/// `poses`, a stream of steps 0, 10, ... 100 (steps 100: complete).
void generation(ViewState& s, int g, bool poses, int64_t genome = -1) {
  if (genome < 0) genome = 10 + g;
  send(s, kChannelRun, run_message("r", 100));
  send(s, kChannelGeneration, generation_message("r", g, genome));
  cppn_genome_t gm = genome_message("r", g, genome, 15.0 + g);
  gm.num_links = 1;  // distinct genes per genome: a new champion each time
  gm.links = {link_t{}};
  gm.links[0].innovation = genome;
  send(s, kChannelGenome, gm);
  send(s, kChannelMorphology, morphology_message("r", g, genome));
  if (poses)
    for (int step = 0; step <= 100; step += 10) send(s, kChannelPose, pose_message("r", g, genome, step, 0.01 * step));
}

TEST(ViewState, LateJoinerGetsRunHistoryChampionsAndPosesSoFar) {
  ViewState s("log", "test.lcmlog");
  generation(s, 0, true);
  generation(s, 1, false);
  generation(s, 2, true);
  send(s, kChannelPose, pose_message("r", 2, 12, 110, 1.0));  // after the stream ended: bad, skipped
  int wakes = 0;
  auto c = s.join([&] { ++wakes; });
  EXPECT_GE(wakes, 1);
  const auto frames = drain(*c);
  EXPECT_EQ(kinds(frames), (std::vector<std::string>{"hello", "run", "history", "champions", "robot", "poses"}));
  EXPECT_EQ(frames[1]["id"], "r");
  ASSERT_EQ(frames[2]["gens"].size(), 3u);
  EXPECT_EQ(frames[2]["gens"][2]["g"], 2);
  EXPECT_EQ(frames[3]["list"].size(), 3u);  // three distinct champions
  EXPECT_EQ(frames[4]["id"], 12);
  EXPECT_EQ(frames[4]["leaf"], (nlohmann::json{0, 0, 1, 1}));
  EXPECT_EQ(frames[5]["list"].size(), 11u);
  EXPECT_EQ(frames[5]["done"], true);
  const ViewCounters v = s.counters();
  EXPECT_EQ(v.bad, 1);
  EXPECT_EQ(v.generations, 3);
  EXPECT_EQ(v.poses, 22);
  EXPECT_EQ(v.pages, 1);
}

TEST(ViewState, JoinedPageGetsEveryFrameThatFollowsOnce) {
  ViewState s("live", "udpm://x");
  generation(s, 0, true);
  auto c = s.join(nullptr);
  drain(*c);
  generation(s, 1, true);
  const auto frames = drain(*c);
  std::vector<std::string> want = {"gen", "champion", "robot"};
  for (int i = 0; i < 11; ++i) want.push_back("pose");
  want.push_back("end");
  EXPECT_EQ(kinds(frames), want);
  EXPECT_EQ(frames[3]["step"], 0);
  EXPECT_EQ(frames[13]["step"], 100);
  s.leave(c);
  EXPECT_EQ(s.counters().pages, 0);
}

TEST(ViewState, SlowPageLosesOldestPosesOnlyAndOthersDoNot) {
  ViewStateOptions o;
  o.queue.max_poses = 4;
  ViewState s("live", "udpm://x", o);
  auto slow = s.join(nullptr);
  // A page that reads each frame as soon as it is woken (as its connection does).
  size_t fast_poses = 0;
  Client* fast_page = nullptr;
  auto fast = s.join([&] {
    if (!fast_page) return;
    for (const auto& f : drain(*fast_page)) fast_poses += f["t"] == "pose";
  });
  fast_page = fast.get();
  drain(*fast);
  for (int g = 0; g < 3; ++g) generation(s, g, true);
  EXPECT_EQ(fast_poses, 33u);
  EXPECT_EQ(fast->queue.counters().dropped_poses, 0);
  const QueueCounters q = slow->queue.counters();
  EXPECT_EQ(q.dropped_poses, 33 - 4);
  const auto frames = drain(*slow);
  size_t gens = 0, robots = 0, poses = 0;
  for (const auto& f : frames) {
    gens += f["t"] == "gen";
    robots += f["t"] == "robot";
    poses += f["t"] == "pose";
  }
  EXPECT_EQ(gens, 3u);
  EXPECT_EQ(robots, 3u);
  EXPECT_EQ(poses, 4u);
  EXPECT_EQ(frames.back()["t"], "end");
  EXPECT_EQ(s.counters().dropped_poses, 29);
  EXPECT_EQ(s.counters().messages, 3 * 15);  // every message was taken in
  const auto stats = nlohmann::json::parse(*s.stats_frame(*slow));
  EXPECT_EQ(stats["dropped"], 29);
  s.leave(slow);
  EXPECT_EQ(s.counters().dropped_poses, 29);  // counted after the page left too
}

TEST(ViewState, BadMessagesAreCountedAndSkipped) {
  ViewState s("live", "udpm://x");
  const std::vector<uint8_t> junk = {1, 2, 3, 4, 5};
  s.ingest(kChannelPose, junk.data(), junk.size());
  s.ingest(kChannelRun, nullptr, 0);
  generation(s, 0, true);
  send(s, kChannelPose, pose_message("r", 0, 10, 5, 0.0, 3));  // sphere count differs
  EXPECT_EQ(s.counters().bad, 3);
  EXPECT_EQ(s.counters().generations, 1);
}

TEST(ViewState, ReplayFromLoggedPosesOrByResimulation) {
  ViewStateOptions o;
  o.keep_streams = 1;
  ViewState s("live", "udpm://x", o);
  generation(s, 0, true);
  generation(s, 1, true);  // genome 10's poses are released: only one stream is kept
  const ReplayPlan logged = s.plan_replay(11);
  ASSERT_TRUE(logged.error.empty());
  ASSERT_EQ(logged.frames.size(), 2u);
  const auto poses = nlohmann::json::parse(*logged.frames[1]);
  EXPECT_EQ(poses["list"].size(), 11u);
  EXPECT_EQ(poses["resimulated"], false);
  const ReplayPlan again = s.plan_replay(10);
  EXPECT_TRUE(again.frames.empty());
  ASSERT_TRUE(again.genome.has_value());  // to be re-simulated, off the lock
  // The hand-made genome does not grow into the hand-made robot: re-simulation refuses it.
  EXPECT_ANY_THROW(s.resimulate(again));
  EXPECT_FALSE(s.plan_replay(999).error.empty());
}

TEST(ViewState, ANewRunStartsThePagesOver) {
  ViewState s("live", "udpm://x");
  generation(s, 0, true);
  auto c = s.join(nullptr);
  drain(*c);
  run_t other = run_message("r2", 100);
  send(s, kChannelRun, other);
  const auto frames = drain(*c);
  ASSERT_EQ(kinds(frames), std::vector<std::string>{"run"});
  EXPECT_EQ(frames[0]["id"], "r2");
  EXPECT_EQ(s.counters().generations, 0);
  generation(s, 5, false);  // run "r" again: not followed any more
  EXPECT_EQ(s.counters().run_id, "r2");
  EXPECT_EQ(s.counters().generations, 0);
}

TEST(ViewState, QuietIntakeEndsWithOneSnapshotPerPage) {
  ViewState s("log", "test.lcmlog");
  auto c = s.join(nullptr);
  drain(*c);
  s.set_quiet(true);
  for (int g = 0; g < 3; ++g) generation(s, g, true);
  EXPECT_FALSE(c->queue.pop().has_value());  // nothing while quiet
  s.set_quiet(false);
  const auto frames = drain(*c);
  EXPECT_EQ(kinds(frames), (std::vector<std::string>{"hello", "run", "history", "champions", "robot", "poses"}));
  EXPECT_EQ(frames[2]["gens"].size(), 3u);
}

}  // namespace
}  // namespace robozoo::view
