#include "runlog/play/player.hpp"

#include <gtest/gtest.h>

#include "evolve/messages/build.hpp"
#include "tests/runlog/fake_clock.hpp"

namespace robozoo {
namespace {

using testing::FakeClock;

struct Sent {
  std::string channel;
  std::vector<uint8_t> data;
  double at;
};

/// Two generations of a run as robozoo-evolve logs them: RUN, GENERATION, GENOME,
/// MORPHOLOGY, then a trajectory of poses written in one burst (1 us apart),
/// sim_time 0.04 s apart; plus an LCM_SELF_TEST.
struct SyntheticLog {
  LogContents log;
  int64_t ts = 1'000'000;
  template <class T>
  void add(const std::string& channel, const T& m, int64_t gap_us) {
    ts += gap_us;
    LogRecord r;
    r.eventnum = static_cast<int64_t>(log.records.size());
    r.timestamp = ts;
    r.channel = channel;
    r.data = encode_message(m);
    log.records.push_back(std::move(r));
  }
  void generation(int g, int64_t genome_id, int poses) {
    run_t run{};
    run.run_id = "r";
    add(kChannelRun, run, 2'000'000);  // generations are 2 s apart
    generation_t gen{};
    gen.run_id = "r";
    gen.generation = g;
    gen.champion_id = genome_id;
    add(kChannelGeneration, gen, 10);
    cppn_genome_t gm{};
    gm.run_id = "r";
    gm.generation = g;
    gm.genome_id = genome_id;
    add(kChannelGenome, gm, 10);
    morphology_t m{};
    m.run_id = "r";
    m.generation = g;
    m.genome_id = genome_id;
    add(kChannelMorphology, m, 10);
    for (int k = 0; k < poses; ++k) {
      pose_t p{};
      p.run_id = "r";
      p.generation = g;
      p.genome_id = genome_id;
      p.step = 4 * k;
      p.sim_time = 0.04 * k;
      add(kChannelPose, p, 1);
    }
  }
  SyntheticLog() {
    LogRecord self;
    self.channel = "LCM_SELF_TEST";
    self.data = {1, 2};
    self.timestamp = ts;
    log.records.push_back(self);
    generation(0, 5, 3);
    generation(1, 8, 4);
  }
};

std::vector<std::string> channels_of(const LogContents& log, const std::vector<PlannedEvent>& plan) {
  std::vector<std::string> out;
  for (const auto& p : plan) out.push_back(log.records[p.record].channel + (p.state ? "*" : ""));
  return out;
}

TEST(Player, PlaysEveryRobozooEventInOrderWithLogGapsAndSimTimePoses) {
  SyntheticLog s;
  const LogIndex ix = index_log(s.log);
  const auto plan = plan_pass(s.log, ix, {});
  ASSERT_EQ(plan.size(), s.log.records.size() - 1);  // all but LCM_SELF_TEST
  for (size_t i = 0; i < plan.size(); ++i) {
    EXPECT_EQ(plan[i].record, i + 1);
    EXPECT_FALSE(plan[i].state);
  }
  // Record 1 is the first RUN (2 s after the self-test), 4-6 the first trajectory.
  EXPECT_NEAR(plan[0].at, 2.0, 1e-12);
  EXPECT_NEAR(plan[3].at - plan[2].at, 10e-6, 1e-12);
  EXPECT_NEAR(plan[4].at - plan[3].at, 1e-6, 1e-12);  // the pose at step 0
  EXPECT_NEAR(plan[5].at - plan[4].at, 0.04, 1e-12);  // poses spaced by simulated time
  EXPECT_NEAR(plan[6].at - plan[5].at, 0.04, 1e-12);
  // The next generation follows 2 s (its log gap) after the stretched trajectory.
  EXPECT_NEAR(plan[7].at - plan[6].at, 2.0, 1e-12);
}

TEST(Player, SpeedDividesTimesAndLogTimeKeepsTheBurst) {
  SyntheticLog s;
  const LogIndex ix = index_log(s.log);
  PlayOptions fast;
  fast.speed = 4.0;
  const auto a = plan_pass(s.log, ix, {});
  const auto b = plan_pass(s.log, ix, fast);
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(b[i].at, a[i].at / 4.0, 1e-12);
  PlayOptions log_time;
  log_time.pace_poses_by_sim_time = false;
  const auto c = plan_pass(s.log, ix, log_time);
  EXPECT_NEAR(c[5].at - c[4].at, 1e-6, 1e-12);
}

TEST(Player, ChannelRegexSelectsWholeNamesAndStateStillComesFirst) {
  SyntheticLog s;
  const LogIndex ix = index_log(s.log);
  PlayOptions poses;
  poses.channels = "ROBOZOO_POSE";
  const auto plan = plan_pass(s.log, ix, poses);
  // The run goes out once per pass; each new genome's genome and morphology before its poses.
  EXPECT_EQ(channels_of(s.log, plan),
            (std::vector<std::string>{"ROBOZOO_RUN*", "ROBOZOO_GENOME*", "ROBOZOO_MORPHOLOGY*", "ROBOZOO_POSE",
                                      "ROBOZOO_POSE", "ROBOZOO_POSE", "ROBOZOO_GENOME*", "ROBOZOO_MORPHOLOGY*",
                                      "ROBOZOO_POSE", "ROBOZOO_POSE", "ROBOZOO_POSE", "ROBOZOO_POSE"}));
  EXPECT_EQ(plan[0].at, plan[3].at);  // state goes out with the first pose
  PlayOptions gens;
  gens.channels = "ROBOZOO_GEN.*";  // matches GENERATION and GENOME, whole names only
  EXPECT_EQ(channels_of(s.log, plan_pass(s.log, ix, gens)),
            (std::vector<std::string>{"ROBOZOO_GENERATION", "ROBOZOO_GENOME", "ROBOZOO_GENERATION", "ROBOZOO_GENOME"}));
  PlayOptions partial;
  partial.channels = "ROBOZOO_GEN";  // not a whole name
  EXPECT_THROW(plan_pass(s.log, ix, partial), std::invalid_argument);
  PlayOptions self;
  self.channels = ".*";
  EXPECT_EQ(plan_pass(s.log, ix, self).size(), s.log.records.size() - 1);  // never LCM_SELF_TEST
}

TEST(Player, StartGenerationBeginsWithThatGenerationsRun) {
  SyntheticLog s;
  const LogIndex ix = index_log(s.log);
  PlayOptions o;
  o.start_generation = 1;
  const auto plan = plan_pass(s.log, ix, o);
  EXPECT_EQ(channels_of(s.log, plan),
            (std::vector<std::string>{"ROBOZOO_RUN", "ROBOZOO_GENERATION", "ROBOZOO_GENOME", "ROBOZOO_MORPHOLOGY",
                                      "ROBOZOO_POSE", "ROBOZOO_POSE", "ROBOZOO_POSE", "ROBOZOO_POSE"}));
  EXPECT_EQ(plan[0].at, 0.0);
  o.start_generation = 2;
  try {
    plan_pass(s.log, ix, o);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("last generation is 1"), std::string::npos) << e.what();
  }
}

TEST(Player, StartingMidRunSendsTheStateFromBeforeTheStart) {
  // Generation 1 re-uses generation 0's champion genome id (its trajectory continues).
  SyntheticLog s;
  s.log.records.resize(1);
  s.generation(0, 5, 2);
  s.ts += 2'000'000;
  generation_t gen{};
  gen.run_id = "r";
  gen.generation = 1;
  gen.champion_id = 5;
  s.add(kChannelGeneration, gen, 10);
  pose_t p{};
  p.run_id = "r";
  p.generation = 1;
  p.genome_id = 5;
  p.step = 8;
  p.sim_time = 0.08;
  s.add(kChannelPose, p, 1);
  const LogIndex ix = index_log(s.log);
  PlayOptions o;
  o.start_generation = 1;
  EXPECT_EQ(channels_of(s.log, plan_pass(s.log, ix, o)),
            (std::vector<std::string>{"ROBOZOO_GENERATION", "ROBOZOO_RUN*", "ROBOZOO_GENOME*", "ROBOZOO_MORPHOLOGY*",
                                      "ROBOZOO_POSE"}));
}

TEST(Player, PlayWaitsOnTheClockAndLoops) {
  SyntheticLog s;
  const LogIndex ix = index_log(s.log);
  FakeClock clock(100.0);
  std::vector<Sent> sent;
  PlayOptions o;
  o.loop = true;
  o.max_passes = 2;
  const PlayStats stats = play(s.log, ix, o, clock, [&](const std::string& ch, const std::vector<uint8_t>& d) {
    sent.push_back({ch, d, clock.t});
    return true;
  });
  const auto plan = plan_pass(s.log, ix, {});
  EXPECT_EQ(stats.passes, 2);
  EXPECT_EQ(stats.events_sent, static_cast<int64_t>(2 * plan.size()));
  EXPECT_EQ(stats.state_events_sent, 0);
  ASSERT_EQ(sent.size(), 2 * plan.size());
  for (size_t i = 0; i < plan.size(); ++i) {
    EXPECT_EQ(sent[i].data, s.log.records[plan[i].record].data);
    EXPECT_NEAR(sent[i].at, 100.0 + plan[i].at, 1e-9);
  }
  // The second pass starts when the first ended.
  EXPECT_NEAR(sent[plan.size()].at, sent[plan.size() - 1].at + plan[0].at, 1e-9);
}

TEST(Player, PublishFailuresAreCounted) {
  SyntheticLog s;
  const LogIndex ix = index_log(s.log);
  FakeClock clock(100.0);
  const PlayStats stats =
      play(s.log, ix, {}, clock, [](const std::string&, const std::vector<uint8_t>&) { return false; });
  EXPECT_EQ(stats.publish_failures, stats.events_sent);
}

TEST(Player, BadOptionsAreRefused) {
  SyntheticLog s;
  const LogIndex ix = index_log(s.log);
  PlayOptions o;
  o.channels = "ROBOZOO_(";
  EXPECT_THROW(plan_pass(s.log, ix, o), std::invalid_argument);
  o = {};
  o.speed = 0;
  EXPECT_THROW(plan_pass(s.log, ix, o), std::invalid_argument);
  o = {};
  o.channels = "NOTHING";
  EXPECT_THROW(plan_pass(s.log, ix, o), std::invalid_argument);
}

}  // namespace
}  // namespace robozoo
