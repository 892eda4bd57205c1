#include "runlog/text/log_cat.hpp"

#include <fcntl.h>  // tests/support/subprocess.hpp uses open()
#include <gtest/gtest.h>

#include <sstream>

#include "evolve/messages/safe_decode.hpp"
#include "tests/render/fixtures.hpp"
#include "tests/render/messages.hpp"
#include "tests/support/subprocess.hpp"

namespace robozoo {
namespace {

using robozoo::testing::TempDir;

std::vector<nlohmann::json> lines(const std::string& text) {
  std::vector<nlohmann::json> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(nlohmann::json::parse(l));
  return out;
}

TEST(LogCat, OneObjectPerMessageWithEveryFieldBitForBit) {
  TempDir dir;
  render::testing::write_small_run(dir / "run.lcmlog");
  const ScannedLog log = scan_event_log(dir / "run.lcmlog");
  std::ostringstream all;
  EXPECT_EQ(cat_log(log, {}, all), static_cast<int64_t>(log.contents.records.size()));
  const auto objects = lines(all.str());
  ASSERT_EQ(objects.size(), log.contents.records.size());
  EXPECT_EQ(objects[0]["channel"], "ROBOZOO_RUN");
  EXPECT_EQ(objects[0]["message"]["run_id"], "feedforward-s7");
  // A generation's doubles read back exactly.
  for (size_t i = 0; i < objects.size(); ++i)
    if (objects[i]["channel"] == "ROBOZOO_GENERATION") {
      generation_t g{};
      ASSERT_TRUE(safe_decode(log.contents.records[i].data.data(), log.contents.records[i].data.size(), g));
      EXPECT_EQ(objects[i]["message"]["mean_fitness"].get<double>(), g.mean_fitness);
      EXPECT_EQ(objects[i]["event"], log.contents.records[i].eventnum);
      break;
    }
  std::ostringstream poses;
  CatFilter f;
  f.channel = "pose";
  f.generation = 2;
  const int64_t n = cat_log(log, f, poses);
  const auto p = lines(poses.str());
  ASSERT_EQ(static_cast<int64_t>(p.size()), n);
  for (const auto& o : p) {
    EXPECT_EQ(o["channel"], "ROBOZOO_POSE");
    EXPECT_EQ(o["message"]["generation"], 2);
    EXPECT_EQ(o["message"]["sphere_center"].size(), o["message"]["num_spheres"].get<size_t>());
  }
}

TEST(LogCat, BadAndForeignMessagesAreMarked) {
  TempDir dir;
  {
    EventLogWriter w = EventLogWriter::create(dir / "odd.lcmlog");
    render::testing::append(w, kChannelRun, render::testing::run_message("r"));
    w.write(kChannelGenome, {1, 2, 3}, 0);
    w.write("LCM_SELF_TEST", {9, 9}, 0);
    w.sync();
  }
  std::ostringstream out;
  cat_log(scan_event_log(dir / "odd.lcmlog"), {}, out);
  const auto o = lines(out.str());
  ASSERT_EQ(o.size(), 3u);
  EXPECT_TRUE(o[1].contains("error"));
  EXPECT_FALSE(o[1].contains("message"));
  EXPECT_EQ(o[2]["bytes"], 2);
  EXPECT_EQ(channel_name("generation"), "ROBOZOO_GENERATION");
  EXPECT_EQ(channel_name("LCM_SELF_TEST"), "LCM_SELF_TEST");
}

}  // namespace
}  // namespace robozoo
