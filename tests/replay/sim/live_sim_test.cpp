#include "replay/sim/live_sim.hpp"

#include <gtest/gtest.h>

#include <map>

#include "evolve/io/log_compare.hpp"
#include "tests/replay/replay_fixtures.hpp"
#include "tests/runlog/fake_clock.hpp"

namespace robozoo::replay {
namespace {

using namespace robozoo::testing;

struct Sent {
  std::string channel;
  std::vector<uint8_t> data;
};

struct Fixture {
  LogContents log = read_event_log(small_run_log());
  LogIndex index = index_log(log);
  const LoggedGenome& with_poses() const {
    for (const auto& g : index.genomes)
      if (!g.pose_events.empty()) return g;
    throw std::runtime_error("no trajectory in the small run");
  }
};

TEST(LiveSim, SendsStateThenEveryStepMatchingTheLoggedTrajectoryBitForBit) {
  Fixture f;
  const LoggedGenome& g = f.with_poses();
  FakeClock clock(50.0);
  std::vector<Sent> sent;
  LiveSimOptions o;
  o.genome_id = g.genome_id;
  o.speed = 2.0;
  const LiveSimStats s =
      live_simulate(f.log, f.index, o, clock, [&](const std::string& c, const std::vector<uint8_t>& d) {
        sent.push_back({c, d});
        return true;
      });
  ASSERT_GE(sent.size(), 4u);
  EXPECT_EQ(sent[0].channel, kChannelRun);
  EXPECT_EQ(sent[1].channel, kChannelGenome);
  EXPECT_EQ(sent[1].data, f.log.records[f.index.events[g.genome_event].record].data);
  EXPECT_EQ(sent[2].channel, kChannelMorphology);
  // The morphology of the grown robot is the logged one (apart from utime).
  std::vector<uint8_t> a, b;
  ASSERT_TRUE(normalize_message(kChannelMorphology, sent[2].data, a));
  ASSERT_TRUE(normalize_message(kChannelMorphology,
                                f.log.records[f.index.events[static_cast<size_t>(g.morphology_event)].record].data, b));
  EXPECT_EQ(a, b);
  // One pose per step, the starting pose included.
  EXPECT_EQ(s.poses_sent, s.steps_run + 1);
  EXPECT_EQ(static_cast<int64_t>(sent.size()), 3 + s.poses_sent);
  EXPECT_TRUE(s.simulated_in_evolution);
  std::map<int, std::vector<uint8_t>> live;
  for (size_t i = 3; i < sent.size(); ++i) {
    ASSERT_EQ(sent[i].channel, kChannelPose);
    const pose_t p = decode_as<pose_t>(LogRecord{0, 0, kChannelPose, sent[i].data});
    EXPECT_EQ(p.step, static_cast<int>(i - 3));
    std::vector<uint8_t> n;
    ASSERT_TRUE(normalize_message(kChannelPose, sent[i].data, n));
    live[p.step] = n;
  }
  for (size_t e : g.pose_events) {
    const LogRecord& r = f.log.records[f.index.events[e].record];
    const pose_t p = decode_as<pose_t>(r);
    std::vector<uint8_t> n;
    ASSERT_TRUE(normalize_message(kChannelPose, r.data, n));
    EXPECT_EQ(live.at(p.step), n) << "step " << p.step;
  }
  // Real time at --speed 2: the last pose waits for half the simulated time.
  ASSERT_EQ(clock.waits.size(), static_cast<size_t>(s.poses_sent));
  EXPECT_DOUBLE_EQ(clock.waits.front(), 50.0);
  const pose_t last = decode_as<pose_t>(LogRecord{0, 0, kChannelPose, sent.back().data});
  EXPECT_DOUBLE_EQ(clock.waits.back(), 50.0 + last.sim_time / 2.0);
}

TEST(LiveSim, PoseEveryThinsTheStreamButKeepsFirstAndLast) {
  Fixture f;
  const LoggedGenome& g = f.with_poses();
  FakeClock clock(50.0);
  std::vector<int> steps;
  LiveSimOptions o;
  o.genome_id = g.genome_id;
  o.pose_every = 7;
  const LiveSimStats s =
      live_simulate(f.log, f.index, o, clock, [&](const std::string& c, const std::vector<uint8_t>& d) {
        if (c == kChannelPose) steps.push_back(decode_as<pose_t>(LogRecord{0, 0, c, d}).step);
        return true;
      });
  ASSERT_FALSE(steps.empty());
  EXPECT_EQ(steps.front(), 0);
  EXPECT_EQ(steps.back(), s.steps_run);
  for (size_t i = 1; i + 1 < steps.size(); ++i) EXPECT_EQ(steps[i] % 7, 0);
}

TEST(LiveSim, UnknownGenomeListsTheLoggedOnes) {
  Fixture f;
  FakeClock clock(50.0);
  LiveSimOptions o;
  o.genome_id = 987654;
  try {
    live_simulate(f.log, f.index, o, clock, [](const std::string&, const std::vector<uint8_t>&) { return true; });
    FAIL();
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("987654"), std::string::npos) << what;
    EXPECT_NE(what.find(std::to_string(f.index.genomes[0].genome_id) + " (gen 0)"), std::string::npos) << what;
  }
  EXPECT_TRUE(clock.waits.empty());
}

TEST(LiveSim, AnotherSoftwareVersionIsRefusedUnlessForced) {
  Fixture f;
  for (auto& r : f.log.records)
    if (r.channel == kChannelRun) {
      run_t m = decode_as<run_t>(r);
      m.software_version = "0.0.0-old";
      r.data = encode_message(m);
    }
  FakeClock clock(50.0);
  LiveSimOptions o;
  o.genome_id = f.with_poses().genome_id;
  int sent = 0;
  auto publish = [&](const std::string&, const std::vector<uint8_t>&) { return ++sent > 0; };
  EXPECT_THROW(live_simulate(f.log, f.index, o, clock, publish), std::invalid_argument);
  EXPECT_EQ(sent, 0);
  o.force = true;
  o.pose_every = 1000;
  EXPECT_NO_THROW(live_simulate(f.log, f.index, o, clock, publish));
  EXPECT_GT(sent, 3);
}

}  // namespace
}  // namespace robozoo::replay
