// robozoo-render live: unit checks, then the real thing on an LCM bus inside a
// private network namespace (docs/method.md section 5), next to robozoo-evolve and
// lcm-logplayer. Runs alone (RUN_SERIAL: the name ends in _live_test).
#include "render/live/live.hpp"

#include <fcntl.h>  // tests/support/subprocess.hpp uses open()
#include <gtest/gtest.h>

#include <filesystem>

#include "render/gl/png_io.hpp"
#include "tests/render/decode_video.hpp"
#include "tests/render/fixtures.hpp"
#include "tests/render/messages.hpp"
#include "tests/support/subprocess.hpp"

namespace robozoo::render {
namespace {

using namespace robozoo::testing;

const std::string kUrl = "udpm://239.255.76.67:7667?ttl=0";

std::vector<std::string> videos_in(const std::string& dir) {
  std::vector<std::string> out;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.path().extension() == ".mp4") out.push_back(e.path().string());
  return out;
}

/// Runs `inner` (a shell script) in a private network namespace with
/// multicast on the loopback interface.
robozoo::testing::Outcome in_namespace(const std::string& inner) {
  return run_shell("timeout 150 unshare -n sh -c \"ip link set lo up && ip route add 224.0.0.0/4 dev lo && " + inner +
                   "\"");
}

std::string live_command(const std::string& out, double idle_exit) {
  return bin("robozoo-render") + " live --lcm-url '" + kUrl + "' --out '" + out + "' --idle-exit " +
         std::to_string(idle_exit) + " --stream-timeout 1.5 --size 320x180 --picture-size 320x240";
}

TEST(Live, FileNamesAndOptions) {
  EXPECT_EQ(safe_file_name("recurrent-s3"), "recurrent-s3");
  EXPECT_EQ(safe_file_name("a/b c"), "a_b_c");
  EXPECT_EQ(safe_file_name(".hidden"), "_hidden");
  EXPECT_EQ(safe_file_name(""), "run");
  LiveOptions o;
  o.url = kUrl;
  o.out_dir = "/tmp/x";
  EXPECT_NO_THROW(validate(o));
  o.idle_exit = 1.0;  // shorter than the stream timeout
  EXPECT_THROW(validate(o), std::invalid_argument);
  o.idle_exit = 0;
  o.video.encoder.height = 181;
  EXPECT_THROW(validate(o), std::invalid_argument);
  o = LiveOptions{};
  EXPECT_THROW(validate(o), std::invalid_argument);  // no URL
}

TEST(Live, PictureAndVideosWhileEvolveRuns) {
  TempDir dir;
  const std::string script =
      "(" + live_command(dir / "out", 3) + " > '" + (dir / "render.txt") + "' 2>&1 & R=\\$!; sleep 1; " +
      bin("robozoo-evolve") + " --log '" + (dir / "run.lcmlog") +
      "' --workers 2 --seed 7 --population 24 --generations 4 --steps 400 --set growth.bias_input=1.0 --quiet "
      "--lcm-url '" +
      kUrl + "'; E=\\$?; wait \\$R; S=\\$?; exit \\$((E * 16 + S)))";
  const robozoo::testing::Outcome o = in_namespace(script);
  const std::string log = read_file(dir / "render.txt");
  ASSERT_EQ(o.status, 0) << o.output << "\n" << log;
  EXPECT_NE(log.find("run feedforward-s7"), std::string::npos) << log;
  ASSERT_TRUE(file_exists(dir / "out/latest.png")) << log;
  const Image latest = read_png(dir / "out/latest.png");
  EXPECT_GT(latest.width(), 320);
  int red = 0, blue = 0;
  for (int y = 0; y < latest.height(); ++y)
    for (int x = 0; x < latest.width(); ++x) {
      const Rgb c = latest.at(x, y);
      red += render::testing::is_red(c.r, c.g, c.b);
      blue += render::testing::is_blue(c.r, c.g, c.b);
    }
  EXPECT_GT(red + blue, 500);
  const std::vector<std::string> v = videos_in(dir / "out");
  ASSERT_GE(v.size(), 1u) << log;
  for (const auto& p : v) {
    const auto d = render::testing::decode_video(p);
    ASSERT_TRUE(d.ok) << p << ": " << d.error;
    EXPECT_EQ(d.codec, "h264");
    EXPECT_EQ(d.width, 320);
    EXPECT_EQ(d.height, 180);
    EXPECT_GE(d.luma.size(), 2u) << p;
    EXPECT_LE(d.luma.size(), 101u) << p;  // at most 400 steps = 4 s at 25 fps, plus the first frame
  }
}

TEST(Live, JoinsMidRunAndSkipsBadMessages) {
  TempDir dir;
  {
    using namespace render::testing;
    EventLogWriter w = EventLogWriter::create(dir / "bus.lcmlog");
    int64_t t = 0;
    auto next = [&] { return t += 2000; };
    // Joined mid-run: the tail of a generation whose ROBOZOO_RUN we missed.
    append(w, kChannelGenome, genome_message("r", 2, 20, 16.0), next());
    append(w, kChannelMorphology, morphology_message("r", 2, 20), next());
    for (int s = 40; s <= 100; s += 4) append(w, kChannelPose, pose_message("r", 2, 20, s, 0.01 * s), next());
    // The next generation, with garbage mixed in.
    append(w, kChannelRun, run_message("r", 100), next());
    append(w, kChannelGeneration, generation_message("r", 3, 30), next());
    w.write(kChannelGenome, {0xde, 0xad, 0xbe, 0xef}, next());
    append(w, kChannelGenome, genome_message("r", 3, 30, 17.0), next());
    append(w, kChannelMorphology, morphology_message("r", 3, 30), next());
    for (int s = 0; s <= 100; s += 4) {
      append(w, kChannelPose, pose_message("r", 3, 30, s, 0.01 * s), next());
      if (s == 48) append(w, kChannelPose, pose_message("r", 3, 30, 50, 0.0, 2), next());  // sizes do not add up
    }
    append(w, kChannelPose, pose_message("r", 3, 30, 100, 1.0), next());
    w.sync();
  }
  const std::string script = "(" + live_command(dir / "out", 3) + " > '" + (dir / "render.txt") +
                             "' 2>&1 & R=\\$!; sleep 1; lcm-logplayer -l '" + kUrl + "' '" + (dir / "bus.lcmlog") +
                             "'; sleep 0.5; wait \\$R; exit \\$?)";
  const robozoo::testing::Outcome o = in_namespace(script);
  const std::string log = read_file(dir / "render.txt");
  ASSERT_EQ(o.status, 0) << o.output << "\n" << log;
  EXPECT_NE(log.find("joined mid-run"), std::string::npos) << log;
  EXPECT_NE(log.find("skipped"), std::string::npos) << log;
  EXPECT_NE(log.find("3 rejected"), std::string::npos) << log;  // garbage, wrong sizes, a pose after its stream
  const std::vector<std::string> v = videos_in(dir / "out");
  ASSERT_EQ(v.size(), 1u) << log;  // generation 3's champion; generation 2's stream was missed
  EXPECT_NE(v[0].find("r_gen0003_genome30.mp4"), std::string::npos);
  const auto d = render::testing::decode_video(v[0]);
  ASSERT_TRUE(d.ok) << d.error;
  EXPECT_EQ(d.luma.size(), 26u);  // 1 s at 25 fps, plus the first frame
  EXPECT_TRUE(file_exists(dir / "out/latest.png"));
}

}  // namespace
}  // namespace robozoo::render
