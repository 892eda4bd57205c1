// check --full: the small run's log re-run from its ROBOZOO_RUN agrees message
// for message; a copy with one link weight of one genome changed, an extra
// event, or a message that does not decode diverges and names it; clock fields
// do not count.
#include "replay/check/full_check.hpp"

#include <gtest/gtest.h>

#include "evolve/io/log_compare.hpp"
#include "tests/replay/replay_fixtures.hpp"

namespace robozoo::replay {
namespace {

using namespace robozoo::testing;

/// Re-runs in process (the evaluator the small run was made with).
FullCheckReport rerun(const std::string& path, FullCheckOptions o = {}, std::vector<int>* calls = nullptr) {
  std::unique_ptr<InProcessEvaluator> evaluator;
  return full_check(
      path,
      [&](const RunConfig& c) -> Evaluator& {
        evaluator = std::make_unique<InProcessEvaluator>(c.eval);
        return *evaluator;
      },
      o,
      [&](int done, int total, double) {
        if (calls) calls->push_back(done * 1000 + total);
      });
}

std::string edited(TempDir& dir, const std::function<bool(size_t, LogRecord&)>& edit) {
  const std::string path = dir / "edited.lcmlog";
  write_log(small_log(), path, edit);
  return path;
}

TEST(FullCheck, TheRealLogIsReproducedMessageForMessage) {
  std::vector<int> calls;
  const FullCheckReport r = rerun(small_run_log(), {}, &calls);
  EXPECT_EQ(r.exit_code(), 0) << format_full_text(r);
  EXPECT_FALSE(r.diverged);
  EXPECT_EQ(r.generations_logged, 4);
  EXPECT_EQ(r.generations_rerun, 4);
  int64_t robozoo = 0;
  for (const auto& rec : small_log().records) robozoo += is_known_channel(rec.channel);
  EXPECT_EQ(r.events_compared, robozoo);
  EXPECT_EQ(calls, (std::vector<int>{1004, 2004, 3004, 4004}));
  EXPECT_EQ(to_json(r)["exit_code"], 0);
}

TEST(FullCheck, OneChangedLinkWeightIsNamed) {
  TempDir dir;
  const int64_t target = nth_on(small_log(), kChannelGenome, 2);
  ASSERT_GE(target, 0);
  double was = 0;
  const std::string path = edited(dir, [&](size_t i, LogRecord& r) {
    if (static_cast<int64_t>(i) != target) return true;
    cppn_genome_t g = decode_as<cppn_genome_t>(r);
    was = g.links.at(5).weight;
    g.links[5].weight = std::nextafter(was, 10.0);  // one ulp
    r.data = encode_message(g);
    return true;
  });
  const FullCheckReport r = rerun(path);
  EXPECT_EQ(r.exit_code(), 1) << format_full_text(r);
  ASSERT_TRUE(r.diverged);
  EXPECT_EQ(r.difference.channel, kChannelGenome);
  EXPECT_EQ(r.difference.logged_eventnum, small_log().records[target].eventnum);
  EXPECT_EQ(r.difference.field, "links[5].weight");
  EXPECT_EQ(r.difference.logged, nlohmann::json(std::nextafter(was, 10.0)).dump());
  EXPECT_EQ(r.difference.rerun, nlohmann::json(was).dump());
  EXPECT_EQ(r.difference.generation, 2);
  EXPECT_LT(r.generations_rerun, 4) << "it stops at the first difference";
  EXPECT_NE(format_full_text(r).find("links[5].weight"), std::string::npos) << format_full_text(r);
}

TEST(FullCheck, ClockFieldsDoNotCountButEverythingElseDoes) {
  TempDir dir;
  const std::string path = edited(dir, [&](size_t, LogRecord& r) {
    if (r.channel != kChannelGeneration) return true;
    generation_t g = decode_as<generation_t>(r);
    g.utime += 12345;
    g.eval_seconds *= 3;
    g.generation_seconds += 1;
    r.data = encode_message(g);
    return true;
  });
  EXPECT_EQ(rerun(path).exit_code(), 0);
  TempDir dir2;
  const std::string species = edited(dir2, [&](size_t, LogRecord& r) {
    if (r.channel != kChannelGeneration) return true;
    generation_t g = decode_as<generation_t>(r);
    g.compatibility_threshold += 1e-9;
    r.data = encode_message(g);
    return true;
  });
  const FullCheckReport r = rerun(species);
  EXPECT_EQ(r.exit_code(), 1);
  EXPECT_EQ(r.difference.field, "compatibility_threshold");
  EXPECT_EQ(r.difference.generation, 0);
}

TEST(FullCheck, ExtraAndUndecodableEventsDiverge) {
  TempDir dir;
  LogContents extra = small_log();
  extra.records.push_back(extra.records[nth_on(extra, kChannelPose, 3)]);
  write_log(extra, dir / "extra.lcmlog");
  const FullCheckReport e = rerun(dir / "extra.lcmlog");
  EXPECT_EQ(e.exit_code(), 1) << format_full_text(e);
  EXPECT_EQ(e.difference.rerun_eventnum, -1);
  EXPECT_NE(e.difference.describe().find("never wrote"), std::string::npos) << e.difference.describe();

  TempDir dir2;
  const int64_t target = nth_on(small_log(), kChannelMorphology, 1);
  const std::string bad = edited(dir2, [&](size_t i, LogRecord& r) {
    if (static_cast<int64_t>(i) == target) r.data[0] ^= 0x40;  // fingerprint
    return true;
  });
  const FullCheckReport u = rerun(bad);
  EXPECT_EQ(u.exit_code(), 1) << format_full_text(u);
  EXPECT_EQ(u.difference.field, "(bytes)");
  EXPECT_EQ(u.difference.logged_eventnum, small_log().records[target].eventnum);
  EXPECT_FALSE(u.input_problems.empty());
}

TEST(FullCheck, AnotherVersionIsRefusedUnlessForcedAndThenLeftOut) {
  TempDir dir;
  const std::string path = edited(dir, [&](size_t, LogRecord& r) {
    if (r.channel != kChannelRun) return true;
    run_t m = decode_as<run_t>(r);
    m.software_version = "0123abcd";
    r.data = encode_message(m);
    return true;
  });
  const FullCheckReport refused = rerun(path);
  EXPECT_EQ(refused.exit_code(), 2);
  EXPECT_NE(refused.fatal.find("0123abcd"), std::string::npos) << refused.fatal;
  EXPECT_EQ(refused.generations_rerun, 0);
  FullCheckOptions force;
  force.force = true;
  EXPECT_EQ(rerun(path, force).exit_code(), 0);
}

TEST(FullCheck, BadInputIsFatal) {
  EXPECT_EQ(rerun("/nonexistent/robozoo.lcmlog").exit_code(), 2);
  TempDir dir;
  const std::string norun = edited(dir, [](size_t, LogRecord& r) { return r.channel != kChannelRun; });
  const FullCheckReport r = rerun(norun);
  EXPECT_EQ(r.exit_code(), 2);
  EXPECT_NE(r.fatal.find("no ROBOZOO_RUN"), std::string::npos);
}

TEST(FullCheck, GenerationsCanBeLimited) {
  FullCheckOptions o;
  o.max_generations = 2;
  const FullCheckReport r = rerun(small_run_log(), o);
  EXPECT_EQ(r.exit_code(), 0) << format_full_text(r);
  EXPECT_EQ(r.generations_rerun, 2);
}

}  // namespace
}  // namespace robozoo::replay
