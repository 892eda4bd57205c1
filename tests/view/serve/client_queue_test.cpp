#include "view/serve/client_queue.hpp"

#include <gtest/gtest.h>

namespace robozoo::view {
namespace {

Frame text(const std::string& s) { return std::make_shared<const std::string>(s); }

TEST(ClientQueue, KeepsOrderAndWakesOnlyWhenEmpty) {
  ClientQueue q;
  EXPECT_TRUE(q.push(text("a"), false));
  EXPECT_FALSE(q.push(text("b"), true));
  EXPECT_EQ(**q.pop(), "a");
  EXPECT_EQ(**q.pop(), "b");
  EXPECT_FALSE(q.pop().has_value());
  EXPECT_TRUE(q.push(text("c"), true));
  const QueueCounters c = q.counters();
  EXPECT_EQ(c.pushed, 3);
  EXPECT_EQ(c.popped, 2);
  EXPECT_EQ(c.waiting, 1u);
  EXPECT_EQ(c.waiting_poses, 1u);
}

TEST(ClientQueue, DropsTheOldestPosesFirstAndKeepsOtherFrames) {
  QueueLimits l;
  l.max_poses = 3;
  ClientQueue q(l);
  q.push(text("robot"), false);
  for (int i = 0; i < 10; ++i) {
    q.push(text("pose" + std::to_string(i)), true);
    if (i == 4) q.push(text("gen"), false);
  }
  const QueueCounters c = q.counters();
  EXPECT_EQ(c.dropped_poses, 7);
  EXPECT_EQ(c.waiting_poses, 3u);
  EXPECT_FALSE(c.overflowed);
  std::vector<std::string> got;
  while (auto f = q.pop()) got.push_back(**f);
  EXPECT_EQ(got, (std::vector<std::string>{"robot", "gen", "pose7", "pose8", "pose9"}));
}

TEST(ClientQueue, TooManyOtherFramesGiveThePageUp) {
  QueueLimits l;
  l.max_other = 4;
  ClientQueue q(l);
  for (int i = 0; i < 4; ++i) q.push(text("gen"), false);
  EXPECT_FALSE(q.counters().overflowed);
  EXPECT_TRUE(q.push(text("gen"), false));  // wakes the writer, which closes
  EXPECT_TRUE(q.counters().overflowed);
  EXPECT_FALSE(q.pop().has_value());
  EXPECT_FALSE(q.push(text("gen"), false));
}

}  // namespace
}  // namespace robozoo::view
