#include "replay/check/champion_check.hpp"

#include <gtest/gtest.h>

#include "replay/log/logged_config.hpp"
#include "tests/replay/replay_fixtures.hpp"

namespace robozoo::replay {
namespace {

using namespace robozoo::testing;

struct Fixture {
  LogContents log = read_event_log(small_run_log());
  RunConfig config = small_run_config();
  /// The first genome with a logged trajectory.
  size_t with_poses(const LogIndex& ix) const {
    for (size_t i = 0; i < ix.genomes.size(); ++i)
      if (!ix.genomes[i].pose_events.empty()) return i;
    throw std::runtime_error("no trajectory in the small run");
  }
};

TEST(ChampionCheck, ALoggedChampionMatchesItsRecomputation) {
  Fixture f;
  const LogIndex ix = index_log(f.log);
  const LoggedGenome& g = ix.genomes[f.with_poses(ix)];
  const ChampionResult r = check_champion(f.log, ix, g, f.config, {});
  EXPECT_EQ(r.status, ChampionResult::Status::Ok);
  EXPECT_TRUE(r.problems.empty());
  EXPECT_TRUE(r.morphology_ok);
  EXPECT_EQ(r.poses_compared, static_cast<int64_t>(g.pose_events.size()));
  EXPECT_EQ(r.poses_expected, r.poses_logged);
  EXPECT_EQ(r.max_error, 0.0);
  EXPECT_GT(r.values_compared, r.poses_compared * 10);
  EXPECT_EQ(r.logged_outcome, r.recomputed_outcome);
  EXPECT_NE(r.recomputed_outcome, 0);
}

TEST(ChampionCheck, ADifferentConfigurationDiverges) {
  Fixture f;
  const LogIndex ix = index_log(f.log);
  RunConfig other = f.config;
  other.eval.sim.friction = 0.5;  // a different world: the poses move differently
  const ChampionResult r = check_champion(f.log, ix, ix.genomes[f.with_poses(ix)], other, {});
  EXPECT_EQ(r.status, ChampionResult::Status::Diverged);
  EXPECT_GT(r.poses_diverged, 0);
  EXPECT_TRUE(r.morphology_ok);  // growth does not depend on friction
  EXPECT_GT(r.first_divergent_step, 0);
}

TEST(ChampionCheck, APoseAfterTheEndOfTheSimulationIsADivergence) {
  Fixture f;
  LogIndex ix = index_log(f.log);
  const size_t gi = f.with_poses(ix);
  LoggedGenome& g = ix.genomes[gi];
  // Append a copy of the last pose, claiming a step past the episode.
  const size_t last = g.pose_events.back();
  pose_t p = decode_as<pose_t>(f.log.records[ix.events[last].record]);
  p.step = f.config.eval.sim.steps + 10;
  LogRecord extra = f.log.records[ix.events[last].record];
  extra.data = encode_message(p);
  f.log.records.push_back(extra);
  IndexedEvent e = ix.events[last];
  e.record = f.log.records.size() - 1;
  ix.events.push_back(e);
  g.pose_events.push_back(ix.events.size() - 1);
  const ChampionResult r = check_champion(f.log, ix, g, f.config, {});
  EXPECT_EQ(r.status, ChampionResult::Status::Diverged);
  EXPECT_EQ(r.poses_diverged, 1);
  // Named twice: as the trajectory's pose after its last one, and as a pose at a
  // step the trajectory does not have.
  ASSERT_EQ(r.mismatches.size(), 2u);
  EXPECT_EQ(r.mismatches[0].what, "trajectory");
  EXPECT_NE(r.mismatches[0].field.find("step"), std::string::npos) << r.mismatches[0].field;
  EXPECT_EQ(r.mismatches[0].logged, std::to_string(p.step));
  EXPECT_NE(r.mismatches[0].recomputed.find("none: the trajectory has"), std::string::npos)
      << r.mismatches[0].recomputed;
  EXPECT_EQ(r.mismatches[1].what, "pose");
  EXPECT_EQ(r.mismatches[1].step, p.step);
  EXPECT_NE(r.mismatches[1].recomputed.find("a step of the trajectory"), std::string::npos)
      << r.mismatches[1].recomputed;
}

TEST(ChampionCheck, AMissingMorphologyMakesItUnusableButTheRestIsChecked) {
  Fixture f;
  LogIndex ix = index_log(f.log);
  LoggedGenome g = ix.genomes[f.with_poses(ix)];
  g.morphology_event = -1;
  const ChampionResult r = check_champion(f.log, ix, g, f.config, {});
  EXPECT_EQ(r.status, ChampionResult::Status::Unusable);
  ASSERT_EQ(r.problems.size(), 1u);
  EXPECT_NE(r.problems[0].find("morphology is not in the log"), std::string::npos);
  EXPECT_GT(r.poses_compared, 0);
  EXPECT_TRUE(r.fitness_compared);
  EXPECT_EQ(r.mismatch_count, 0);
}

TEST(ChampionCheck, ACycleInAFeedForwardRunIsReported) {
  Fixture f;
  const LogIndex ix = index_log(f.log);
  const LoggedGenome& g = ix.genomes[0];
  LogContents log = f.log;
  LogRecord& rec = log.records[ix.events[g.genome_event].record];
  cppn_genome_t m = decode_as<cppn_genome_t>(rec);
  // A cycle between two outputs: 9 -> 10 -> 9.
  link_t a{}, b{};
  a.innovation = 1000000;
  a.from_node = 9;
  a.to_node = 10;
  a.weight = 0.5;
  a.enabled = true;
  b = a;
  b.innovation = 1000001;
  b.from_node = 10;
  b.to_node = 9;
  m.links.push_back(a);
  m.links.push_back(b);
  m.num_links = static_cast<int32_t>(m.links.size());
  rec.data = encode_message(m);
  const ChampionResult r = check_champion(log, ix, g, f.config, {});
  EXPECT_EQ(r.status, ChampionResult::Status::Diverged);
  ASSERT_FALSE(r.mismatches.empty());
  EXPECT_EQ(r.mismatches[0].what, "genome");
  EXPECT_EQ(r.mismatches[0].field, "links");
}

TEST(ChampionCheck, StatusNames) {
  EXPECT_STREQ(status_name(ChampionResult::Status::Ok), "ok");
  EXPECT_STREQ(status_name(ChampionResult::Status::Diverged), "diverged");
  EXPECT_STREQ(status_name(ChampionResult::Status::Unusable), "unusable");
}

}  // namespace
}  // namespace robozoo::replay
