#include "render/video/bench.hpp"

#include <fcntl.h>  // tests/support/subprocess.hpp uses open()
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

#include "tests/render/fixtures.hpp"
#include "tests/support/subprocess.hpp"

namespace robozoo::render {
namespace {

using robozoo::testing::TempDir;

// The benchmark draws frames with the background last and first (its drawing
// baseline), makes the champion's video twice, side by side and in turn (its
// video baseline), and reports each one's wall and CPU time; it leaves no file behind.
TEST(RenderBench, MeasuresBothWaysOfMakingTheVideoAndCleansUp) {
  TempDir dir;
  testing::write_small_run(dir / "run.lcmlog");
  const std::string scratch = dir / "scratch";
  std::filesystem::create_directories(scratch);
  BenchOptions o;
  o.log = dir / "run.lcmlog";
  o.frames = 5;
  o.scratch = scratch;
  o.video.encoder.width = 320;
  o.video.encoder.height = 180;
  o.video.speed = 4.0;
  const BenchFigures f = run_bench(o);
  EXPECT_GT(f.spheres, 0);
  EXPECT_GT(f.draw_fps, 0);
  EXPECT_GT(f.encode_fps, 0);
  EXPECT_GT(f.draw_cpu_ms, 0);
  EXPECT_GT(f.draw_cpu_ms_before, 0);
  EXPECT_EQ(f.drawn_frames, 5);
  EXPECT_EQ(f.frames_differing, 0);  // the background's order changes no pixel
  EXPECT_GT(f.encode_cpu_ms, 0);
  EXPECT_GT(f.video_frames, 1);
  EXPECT_GT(f.video_wall_seconds, 0);
  EXPECT_GT(f.video_cpu_seconds, 0);
  EXPECT_GT(f.serial_wall_seconds, 0);
  EXPECT_GT(f.serial_cpu_seconds, 0);
  EXPECT_GE(f.cores, 1);
  // The same frames encoded with the settings given and with --fast's.
  EXPECT_EQ(f.encoded_frames, 5);
  EXPECT_EQ(f.given.preset, "veryfast");
  EXPECT_EQ(f.given.threads, 1);
  EXPECT_EQ(f.fast.preset, "superfast");
  EXPECT_EQ(f.fast.threads, 0);
  for (const BenchFigures::Encoding* e : {&f.given, &f.fast}) {
    EXPECT_GT(e->wall_seconds, 0);
    EXPECT_GT(e->cpu_ms, 0);
    EXPECT_GT(e->bytes, 0);
    EXPECT_GT(e->psnr_y, 25.0);  // crf 23 of rendered frames: far from noise
    EXPECT_LT(e->psnr_y, 80.0);  // and lossy
    EXPECT_GT(e->ssim_y, 0.8);
    EXPECT_LT(e->ssim_y, 1.0);
  }
  EXPECT_NE(f.given.bytes, f.fast.bytes);
  EXPECT_GT(f.fast_video_wall_seconds, 0);
  EXPECT_GT(f.fast_video_cpu_seconds, 0);
  EXPECT_GT(f.video_bytes, 0);
  EXPECT_GT(f.fast_video_bytes, 0);
  EXPECT_TRUE(std::filesystem::is_empty(scratch));
  std::ostringstream out;
  print(out, f);
  EXPECT_NE(out.str().find("baseline"), std::string::npos) << out.str();
  EXPECT_NE(out.str().find("cores busy"), std::string::npos) << out.str();
  EXPECT_NE(out.str().find("background drawn first"), std::string::npos) << out.str();
  EXPECT_NE(out.str().find("encoding thread alone"), std::string::npos) << out.str();
  EXPECT_NE(out.str().find("fast/default"), std::string::npos) << out.str();
  EXPECT_NE(out.str().find("superfast"), std::string::npos) << out.str();
}

}  // namespace
}  // namespace robozoo::render
