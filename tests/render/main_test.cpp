// robozoo-render as a user runs it: zoo sheets and videos from logs, and clear
// errors with a non-zero exit for bad input.
#include <fcntl.h>  // tests/support/subprocess.hpp uses open()
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include <nlohmann/json.hpp>

#include "render/gl/png_io.hpp"
#include "tests/render/decode_video.hpp"
#include "tests/render/fixtures.hpp"
#include "tests/render/messages.hpp"
#include "tests/support/subprocess.hpp"

namespace robozoo::render {
namespace {

using namespace robozoo::testing;

class RenderCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new TempDir;
    render::testing::write_small_run(*dir_ / "run.lcmlog");
    // A second run: another seed.
    RunConfig c = render::testing::small_config();
    c.seed = 8;
    InProcessEvaluator ev(c.eval);
    EvolveOptions o;
    o.log_path = *dir_ / "run8.lcmlog";
    Evolution(c, o, ev).run();
  }
  static void TearDownTestSuite() { delete dir_; }
  static robozoo::testing::Outcome cli(const std::string& args) {
    return run_shell(bin("robozoo-render") + " " + args);
  }
  static std::string path(const std::string& name) { return *dir_ / name; }
  static TempDir* dir_;
};
TempDir* RenderCli::dir_ = nullptr;

TEST_F(RenderCli, HelpListsTheSubcommands) {
  const robozoo::testing::Outcome o = cli("--help");
  EXPECT_EQ(o.status, 0);
  for (const char* s : {"zoo", "video", "live", "bench"}) EXPECT_NE(o.output.find(s), std::string::npos) << s;
  EXPECT_NE(cli("").status, 0);  // a subcommand is required
}

TEST_F(RenderCli, ZooOfOneLogAndOfSeveral) {
  const robozoo::testing::Outcome one =
      cli("zoo " + path("run.lcmlog") + " --top 3 --cell 120x90 --columns 3 -o " + path("top.png"));
  ASSERT_EQ(one.status, 0) << one.output;
  const Image top = read_png(path("top.png"));
  EXPECT_EQ(top.width(), 12 + 3 * (120 + 12));
  const robozoo::testing::Outcome two =
      cli("zoo " + path("run.lcmlog") + " " + path("run8.lcmlog") + " --cell 120x90 -o " + path("best.png"));
  ASSERT_EQ(two.status, 0) << two.output;
  EXPECT_NE(two.output.find("2 robots"), std::string::npos) << two.output;  // best of each run
  const robozoo::testing::Outcome gen =
      cli("zoo " + path("run.lcmlog") + " --generation 2 --cell 120x90 -o " + path("g2.png"));
  ASSERT_EQ(gen.status, 0) << gen.output;
  EXPECT_NE(gen.output.find("1 robots"), std::string::npos) << gen.output;
}

TEST_F(RenderCli, VideoOfTheChampion) {
  const robozoo::testing::Outcome o =
      cli("video " + path("run.lcmlog") + " --size 160x90 --speed 8 -o " + path("c.mp4"));
  ASSERT_EQ(o.status, 0) << o.output;
  const auto v = render::testing::decode_video(path("c.mp4"));
  ASSERT_TRUE(v.ok) << v.error;
  EXPECT_EQ(v.codec, "h264");
  EXPECT_EQ(v.width, 160);
  EXPECT_EQ(v.height, 90);
  EXPECT_EQ(v.luma.size(), 13u);  // 4 s at x8 and 25 fps, plus the first frame
  const robozoo::testing::Outcome re =
      cli("video " + path("run.lcmlog") + " --resimulate --size 160x90 --speed 8 -o " + path("r.mp4"));
  ASSERT_EQ(re.status, 0) << re.output;
  EXPECT_NE(re.output.find("re-simulated"), std::string::npos) << re.output;
}

std::string file_bytes(const std::string& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

// --fast trades the byte-reproducible default for speed: a valid H.264 MP4 of
// the same frames and duration, other bytes; the default keeps its settings
// (veryfast on one libx264 thread), byte for byte.
TEST_F(RenderCli, FastVideoIsValidAndTheDefaultKeepsItsBytes) {
  const std::string common = "video " + path("run.lcmlog") + " --size 160x90 --speed 8 -q -o ";
  const robozoo::testing::Outcome d = cli(common + path("default.mp4"));
  ASSERT_EQ(d.status, 0) << d.output;
  const robozoo::testing::Outcome e = cli(common + path("explicit.mp4") + " --preset veryfast --threads 1");
  ASSERT_EQ(e.status, 0) << e.output;
  const robozoo::testing::Outcome f = cli(common + path("fast.mp4") + " --fast");
  ASSERT_EQ(f.status, 0) << f.output;
  EXPECT_EQ(file_bytes(path("default.mp4")), file_bytes(path("explicit.mp4")));
  EXPECT_NE(file_bytes(path("default.mp4")), file_bytes(path("fast.mp4")));
  const auto dv = render::testing::decode_video(path("default.mp4"));
  const auto fv = render::testing::decode_video(path("fast.mp4"));
  ASSERT_TRUE(dv.ok) << dv.error;
  ASSERT_TRUE(fv.ok) << fv.error;
  EXPECT_EQ(fv.codec, "h264");
  EXPECT_EQ(fv.pix_fmt, "yuv420p");
  EXPECT_EQ(fv.width, 160);
  EXPECT_EQ(fv.height, 90);
  EXPECT_TRUE(fv.moov_before_mdat);
  EXPECT_EQ(dv.luma.size(), 13u);  // 4 s at x8 and 25 fps, plus the first frame
  EXPECT_EQ(fv.luma.size(), dv.luma.size());
  EXPECT_DOUBLE_EQ(fv.fps, dv.fps);
  EXPECT_NEAR(dv.duration, 13 / 25.0, 1e-9);
  EXPECT_DOUBLE_EQ(fv.duration, dv.duration);
  // The same pictures, encoded another way: close, frame by frame.
  for (size_t i = 0; i < fv.luma.size() && i < dv.luma.size(); ++i)
    EXPECT_LT(render::testing::luma_difference(fv.luma[i], dv.luma[i]), 4.0) << "frame " << i;
}

TEST_F(RenderCli, FastRefusesThePresetAndThreadsItSets) {
  const robozoo::testing::Outcome help = cli("video --help");
  EXPECT_EQ(help.status, 0);
  EXPECT_NE(help.output.find("--fast"), std::string::npos) << help.output;
  EXPECT_NE(help.output.find("no longer byte-reproducible"), std::string::npos) << help.output;
  for (const std::string extra : {"--fast --preset medium", "--preset veryfast --fast", "--fast --threads 1"}) {
    const robozoo::testing::Outcome o = cli("video " + path("run.lcmlog") + " " + extra + " -o " + path("both.mp4"));
    EXPECT_EQ(o.status, 2) << extra;
    EXPECT_NE(o.output.find("give --fast or --preset/--threads, not both"), std::string::npos) << o.output;
    EXPECT_FALSE(file_exists(path("both.mp4")));
  }
  const robozoo::testing::Outcome b = cli("bench " + path("run.lcmlog") + " --fast");
  EXPECT_EQ(b.status, 2);
  EXPECT_NE(b.output.find("leave out --fast"), std::string::npos) << b.output;
}

TEST_F(RenderCli, MissingLog) {
  for (const std::string cmd : {"zoo ", "video "}) {
    const robozoo::testing::Outcome o = cli(cmd + path("nope.lcmlog") + " -o " + path("x.out"));
    EXPECT_NE(o.status, 0);
    EXPECT_NE(o.output.find("nope.lcmlog: no such log file"), std::string::npos) << o.output;
  }
}

TEST_F(RenderCli, TruncatedLog) {
  std::filesystem::copy_file(path("run.lcmlog"), path("cut.lcmlog"), std::filesystem::copy_options::overwrite_existing);
  std::filesystem::resize_file(path("cut.lcmlog"), std::filesystem::file_size(path("cut.lcmlog")) - 77);
  const robozoo::testing::Outcome o = cli("zoo " + path("cut.lcmlog") + " -o " + path("cut.png"));
  EXPECT_NE(o.status, 0);
  EXPECT_NE(o.output.find("truncated"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("--allow-truncated"), std::string::npos) << o.output;
  const robozoo::testing::Outcome ok =
      cli("zoo " + path("cut.lcmlog") + " --allow-truncated --cell 64x48 -o " + path("cut.png"));
  EXPECT_EQ(ok.status, 0) << ok.output;
}

TEST_F(RenderCli, ZooOfARunningExperimentsFolderOfLogs) {
  // Its runs folder: two trials' logs, the second one ending mid-event, and a
  // trial just started, whose log is still empty.
  const std::string runs = path("runs");
  std::filesystem::create_directory(runs);
  std::filesystem::copy_file(path("run.lcmlog"), runs + "/recurrent-s7.lcmlog");
  std::filesystem::copy_file(path("run8.lcmlog"), runs + "/recurrent-s8.lcmlog");
  std::filesystem::resize_file(runs + "/recurrent-s8.lcmlog",
                               std::filesystem::file_size(runs + "/recurrent-s8.lcmlog") - 77);
  std::ofstream(runs + "/recurrent-s9.lcmlog") << "";
  const robozoo::testing::Outcome o = cli("zoo " + runs + " -q --cell 120x90 -o " + path("runs.png"));
  ASSERT_EQ(o.status, 0) << o.output;
  EXPECT_NE(o.output.find("left out " + runs + "/recurrent-s9.lcmlog: "), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("(2 robots)"), std::string::npos) << o.output;
  EXPECT_EQ(read_png(path("runs.png")).width(), 12 + 2 * (120 + 12));
  // Nothing to draw yet: a clear error, no picture.
  const std::string started = path("started");
  std::filesystem::create_directory(started);
  std::ofstream(started + "/recurrent-s9.lcmlog") << "";
  const robozoo::testing::Outcome none = cli("zoo " + started + " -o " + path("none.png"));
  EXPECT_NE(none.status, 0);
  EXPECT_NE(none.output.find("no trial has a champion yet"), std::string::npos) << none.output;
  EXPECT_FALSE(file_exists(path("none.png")));
}

TEST_F(RenderCli, LogWithoutChampions) {
  {
    EventLogWriter w = EventLogWriter::create(path("empty-run.lcmlog"));
    render::testing::append(w, kChannelRun, render::testing::run_message("r"));
    render::testing::append(w, kChannelGeneration, render::testing::generation_message("r", 0, 1));
    w.sync();
  }
  const robozoo::testing::Outcome z = cli("zoo " + path("empty-run.lcmlog") + " -o " + path("e.png"));
  EXPECT_NE(z.status, 0);
  EXPECT_NE(z.output.find("no log holds a champion"), std::string::npos) << z.output;
  const robozoo::testing::Outcome v = cli("video " + path("empty-run.lcmlog") + " -o " + path("e.mp4"));
  EXPECT_NE(v.status, 0);
  EXPECT_NE(v.output.find("no champion"), std::string::npos) << v.output;
  EXPECT_FALSE(file_exists(path("e.png")));
  EXPECT_FALSE(file_exists(path("e.mp4")));
  // Not a log at all.
  { std::ofstream(path("text.lcmlog")) << "just some text"; }
  const robozoo::testing::Outcome t = cli("zoo " + path("text.lcmlog") + " -o " + path("t.png"));
  EXPECT_NE(t.status, 0);
  EXPECT_NE(t.output.find("not a robozoo-evolve log"), std::string::npos) << t.output;
}

TEST_F(RenderCli, OddAndMalformedVideoSizes) {
  const robozoo::testing::Outcome odd = cli("video " + path("run.lcmlog") + " --size 641x360 -o " + path("odd.mp4"));
  EXPECT_EQ(odd.status, 2);
  EXPECT_NE(odd.output.find("must be even"), std::string::npos) << odd.output;
  EXPECT_FALSE(file_exists(path("odd.mp4")));
  const robozoo::testing::Outcome odd_h = cli("video " + path("run.lcmlog") + " --size 640x361 -o " + path("odd.mp4"));
  EXPECT_EQ(odd_h.status, 2);
  const robozoo::testing::Outcome bad = cli("video " + path("run.lcmlog") + " --size large -o " + path("odd.mp4"));
  EXPECT_NE(bad.status, 0);
  EXPECT_NE(bad.output.find("WIDTHxHEIGHT"), std::string::npos) << bad.output;
  const robozoo::testing::Outcome top =
      cli("zoo " + path("run.lcmlog") + " " + path("run8.lcmlog") + " --top 2 -o " + path("x.png"));
  EXPECT_NE(top.status, 0);
  EXPECT_NE(top.output.find("--top takes one log"), std::string::npos) << top.output;
}

// ---- compact results (the committed paper-size experiment's M2) ------------

const std::string kM2Results = std::string(ROBOZOO_SOURCE_DIR) + "/media/experiment/paper/m2/results";

robozoo::testing::Outcome render_cli(const std::string& args) { return run_shell(bin("robozoo-render") + " " + args); }

/// Pixels of a robot's colours (red leaves, blue others, shaded) in a cell.
int robot_pixels(const Image& sheet, int x0, int y0, int w, int h) {
  int n = 0;
  for (int y = y0; y < y0 + h; ++y)
    for (int x = x0; x < x0 + w; ++x) {
      const uint8_t* p = sheet.row(y) + 3 * x;
      const bool red = p[0] > 100 && p[0] > p[1] + 60 && p[0] > p[2] + 60;
      const bool blue = p[2] > 100 && p[2] > p[0] + 100;
      n += red || blue ? 1 : 0;
    }
  return n;
}

/// Two results of each arm, copied into `dir` (a folder of compact results).
void copy_two_per_arm(const std::string& dir) {
  std::filesystem::create_directory(dir);
  for (const char* name : {"feedforward-s1", "feedforward-s5", "recurrent-s2", "recurrent-s6"})
    std::filesystem::copy_file(kM2Results + "/" + name + ".results.json", dir + "/" + name + ".results.json");
}

TEST(RenderResultsCli, ZooOfTheCommittedM2ResultsDrawsSixtyRobots) {
  TempDir dir;
  const robozoo::testing::Outcome o = render_cli("zoo " + kM2Results + " -o " + (dir / "zoo.png"));
  ASSERT_EQ(o.status, 0) << o.output;
  EXPECT_NE(o.output.find("60 robots reproduce their committed fitness"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("(60 robots)"), std::string::npos) << o.output;
  const Image sheet = read_png(dir / "zoo.png");
  // 60 cells of 360x270 in 11 columns (about sqrt(2 n)) and 6 rows, 12 px apart.
  const int gap = 12, columns = 11, rows = 6;
  EXPECT_EQ(sheet.width(), gap + columns * (360 + gap));
  const int pitch = (sheet.height() - gap) / rows;
  EXPECT_EQ(sheet.height(), gap + rows * pitch);
  EXPECT_GT(pitch, 270 + gap);
  for (int i = 0; i < 60; ++i)
    EXPECT_GT(robot_pixels(sheet, gap + (i % columns) * (360 + gap), gap + (i / columns) * pitch, 360, 270), 1000)
        << "tile " << i;
  // The cells after the 60th are empty paper.
  EXPECT_EQ(robot_pixels(sheet, gap + 5 * (360 + gap), gap + 5 * pitch, 360, 270), 0);
}

TEST(RenderResultsCli, ZooOfAFolderOfCompactResultsDrawsEveryTrialsBestRobot) {
  TempDir dir;
  copy_two_per_arm(dir / "results");
  const robozoo::testing::Outcome o =
      render_cli("zoo " + (dir / "results") + " --jobs 2 --cell 160x120 --columns 2 -o " + (dir / "zoo.png"));
  ASSERT_EQ(o.status, 0) << o.output;
  EXPECT_NE(o.output.find("4 robots reproduce their committed fitness"), std::string::npos) << o.output;
  const Image sheet = read_png(dir / "zoo.png");
  const int gap = 12;
  EXPECT_EQ(sheet.width(), gap + 2 * (160 + gap));
  ASSERT_GT(sheet.height(), gap + 2 * (120 + gap));
  const int row = (sheet.height() - gap) / 2;
  for (int i = 0; i < 4; ++i)
    EXPECT_GT(robot_pixels(sheet, gap + (i % 2) * (160 + gap), gap + (i / 2) * row, 160, 120), 200) << "tile " << i;
  // The same sheet on one thread.
  const robozoo::testing::Outcome one =
      render_cli("zoo " + (dir / "results") + " --jobs 1 -q --cell 160x120 --columns 2 -o " + (dir / "one.png"));
  ASSERT_EQ(one.status, 0) << one.output;
  EXPECT_EQ(read_file(dir / "one.png"), read_file(dir / "zoo.png"));
  // Files as well as folders; not mixed with logs.
  const robozoo::testing::Outcome files =
      render_cli("zoo " + (dir / "results/recurrent-s2.results.json") + " -q --cell 160x120 -o " + (dir / "r2.png"));
  ASSERT_EQ(files.status, 0) << files.output;
  EXPECT_NE(files.output.find("1 robots"), std::string::npos) << files.output;
  const robozoo::testing::Outcome mixed =
      render_cli("zoo " + (dir / "results") + " " + (dir / "run.lcmlog") + " -o " + (dir / "m.png"));
  EXPECT_EQ(mixed.status, 2) << mixed.output;
  EXPECT_NE(mixed.output.find("not both"), std::string::npos) << mixed.output;
  const robozoo::testing::Outcome top = render_cli("zoo " + (dir / "results") + " --top 2 -o " + (dir / "m.png"));
  EXPECT_EQ(top.status, 2) << top.output;
  EXPECT_FALSE(file_exists(dir / "m.png"));
}

TEST(RenderResultsCli, ARobotThatDoesNotReproduceIsRefusedByName) {
  TempDir dir;
  copy_two_per_arm(dir / "results");
  // The genome of one trial altered: every CPPN weight negated.
  const std::string edited = dir / "results/recurrent-s6.results.json";
  nlohmann::json j = nlohmann::json::parse(read_file(edited));
  for (auto& link : j["best"]["genome"]["links"]) link["weight"] = -link["weight"].get<double>();
  std::ofstream(edited) << j.dump();
  const robozoo::testing::Outcome o = render_cli("zoo " + (dir / "results") + " --jobs 2 -o " + (dir / "zoo.png"));
  EXPECT_EQ(o.status, 1) << o.output;
  EXPECT_NE(o.output.find("recurrent-s6.results.json: genome"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("with this build, the result says"), std::string::npos) << o.output;
  EXPECT_FALSE(file_exists(dir / "zoo.png"));
  const robozoo::testing::Outcome v = render_cli("video " + edited + " -q -o " + (dir / "v.mp4"));
  EXPECT_EQ(v.status, 1) << v.output;
  EXPECT_NE(v.output.find("recurrent-s6"), std::string::npos) << v.output;
  EXPECT_FALSE(file_exists(dir / "v.mp4"));
  // Not compact results at all.
  const robozoo::testing::Outcome bad = render_cli("zoo " + (dir / "absent.results.json") + " -o " + (dir / "a.png"));
  EXPECT_NE(bad.status, 0);
  EXPECT_NE(bad.output.find("absent.results.json"), std::string::npos) << bad.output;
}

TEST(RenderResultsCli, VideoOfTheMedianRobotOfSeveralResults) {
  TempDir dir;
  copy_two_per_arm(dir / "results");
  const robozoo::testing::Outcome o = render_cli(
      "video " + (dir / "results/feedforward-s1.results.json") + " " + (dir / "results/feedforward-s5.results.json") +
      " --pick median --size 160x120 --fps 5 --speed 25 --samples 0 -o " + (dir / "m.mp4"));
  ASSERT_EQ(o.status, 0) << o.output;
  EXPECT_NE(o.output.find("median of 2 best-of-run robots"), std::string::npos) << o.output;
  const auto v = render::testing::decode_video(dir / "m.mp4");
  ASSERT_TRUE(v.ok) << v.error;
  EXPECT_EQ(v.width, 160);
  EXPECT_EQ(v.luma.size(), 6u);  // 25 s at x25 and 5 fps, plus the first frame
  const robozoo::testing::Outcome pick =
      render_cli("video " + (dir / "results") + " --pick mean -o " + (dir / "x.mp4"));
  EXPECT_NE(pick.status, 0);
  const robozoo::testing::Outcome gen =
      render_cli("video " + (dir / "results") + " --generation 3 -o " + (dir / "x.mp4"));
  EXPECT_EQ(gen.status, 2) << gen.output;
  EXPECT_FALSE(file_exists(dir / "x.mp4"));
}

}  // namespace
}  // namespace robozoo::render
