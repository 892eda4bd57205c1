#include "runlog/text/log_summary.hpp"

#include <fcntl.h>  // tests/support/subprocess.hpp uses open()
#include <gtest/gtest.h>

#include <filesystem>

#include "evolve/messages/build.hpp"
#include "tests/render/fixtures.hpp"
#include "tests/support/subprocess.hpp"

namespace robozoo {
namespace {

using robozoo::testing::TempDir;

TEST(LogSummary, ChannelsRunsGenerationsAndChampions) {
  TempDir dir;
  render::testing::write_small_run(dir / "run.lcmlog");
  const LogSummary s = summarize_log(scan_event_log(dir / "run.lcmlog"), "run.lcmlog");
  int64_t total = 0;
  for (const auto& [name, c] : s.channels) total += c.messages;
  EXPECT_EQ(total, s.events);
  EXPECT_EQ(s.channels.at("ROBOZOO_GENERATION").messages, 4);
  ASSERT_EQ(s.runs.size(), 1u);
  const RunSummaryLine& r = s.runs[0];
  EXPECT_EQ(r.run_id, "feedforward-s7");
  EXPECT_EQ(r.seed, 7);
  EXPECT_EQ(r.generations, 4);
  EXPECT_EQ(r.first_generation, 0);
  EXPECT_EQ(r.last_generation, 3);
  EXPECT_GE(r.champions, 1);
  EXPECT_LE(r.champions, 4);
  EXPECT_GE(r.pose_streams, 1);
  EXPECT_EQ(r.software_version, software_version());
  EXPECT_TRUE(s.damage.empty());
  const std::string text = format_summary(s);
  EXPECT_NE(text.find("generations: 4 of 4 (0 to 3)"), std::string::npos) << text;
  EXPECT_EQ(to_json(s)["runs"][0]["generations"], 4);
}

TEST(LogSummary, DamageIsReported) {
  TempDir dir;
  render::testing::write_small_run(dir / "run.lcmlog");
  std::filesystem::resize_file(dir / "run.lcmlog", std::filesystem::file_size(dir / "run.lcmlog") - 10);
  const LogSummary s = summarize_log(scan_event_log(dir / "run.lcmlog"), "cut");
  ASSERT_EQ(s.damage.size(), 1u);
  EXPECT_NE(format_summary(s).find("damage: the log ends inside an event"), std::string::npos);
}

}  // namespace
}  // namespace robozoo
