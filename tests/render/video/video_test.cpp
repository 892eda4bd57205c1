#include "render/video/video.hpp"

#include <fcntl.h>  // tests/support/subprocess.hpp uses open()
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "runlog/read/log_source.hpp"
#include "runlog/robots/selection.hpp"
#include "render/video/video_subject.hpp"
#include "tests/render/decode_video.hpp"
#include "tests/render/fixtures.hpp"
#include "tests/support/subprocess.hpp"

namespace robozoo::render {
namespace {

using robozoo::testing::TempDir;

class VideoFromLog : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new TempDir;
    testing::write_small_run(*dir_ / "run.lcmlog");
  }
  static void TearDownTestSuite() { delete dir_; }
  static TempDir* dir_;
};
TempDir* VideoFromLog::dir_ = nullptr;

VideoOptions small_video() {
  VideoOptions o;
  o.encoder.width = 320;
  o.encoder.height = 180;
  o.encoder.fps = 25;
  o.speed = 2.0;  // 4 s of simulation in 2 s of video
  return o;
}

TEST_F(VideoFromLog, H264OfTheExpectedFramesAndSizeThatMoves) {
  const LoadedLog log = load_log(*dir_ / "run.lcmlog");
  const std::vector<Pick> best = best_of_run(log.runs());
  ASSERT_EQ(best.size(), 1u);
  const VideoSubject subject = make_video_subject(*best[0].run, *best[0].genome);
  EXPECT_FALSE(subject.trajectory.resimulated);  // the champion's poses are in the log
  EXPECT_EQ(subject.trajectory.step.back(), 400);
  EXPECT_EQ(subject.target, Eigen::Vector3d(50, 0, 0));
  const VideoOptions o = small_video();
  const int expected = video_frame_count(subject.trajectory.end_time() - subject.trajectory.start_time(), o);
  EXPECT_EQ(expected, 51);  // 4 s / 2 x 25 fps + the first frame

  int progress_calls = 0;
  const VideoStats s = render_video(subject, o, *dir_ / "champ.mp4", [&](int done, int total) {
    ++progress_calls;
    EXPECT_EQ(total, expected);
    EXPECT_EQ(done, progress_calls);
  });
  EXPECT_EQ(s.frames, expected);
  EXPECT_EQ(progress_calls, expected);

  const auto v = testing::decode_video(*dir_ / "champ.mp4");
  ASSERT_TRUE(v.ok) << v.error;
  EXPECT_EQ(v.codec, "h264");
  EXPECT_EQ(v.pix_fmt, "yuv420p");
  EXPECT_EQ(v.width, 320);
  EXPECT_EQ(v.height, 180);
  ASSERT_EQ(static_cast<int>(v.luma.size()), expected);
  EXPECT_TRUE(v.moov_before_mdat);

  // While the robot moves, consecutive frames differ (beyond the overlay's
  // clock: compare with the overlay's change alone by a threshold).
  const Trajectory& tr = subject.trajectory;
  int moving = 0, differ = 0;
  for (int i = 1; i < expected; ++i) {
    const double t0 = std::min(tr.end_time(), (i - 1) * o.speed / o.encoder.fps);
    const double t1 = std::min(tr.end_time(), i * o.speed / o.encoder.fps);
    double moved = 0;
    const auto a = tr.sample(t0), b = tr.sample(t1);
    for (size_t k = 0; k < a.size(); ++k) moved = std::max(moved, (a[k] - b[k]).norm());
    if (moved < 0.002) continue;
    ++moving;
    differ += testing::luma_difference(v.luma[static_cast<size_t>(i - 1)], v.luma[static_cast<size_t>(i)]) > 0.05;
  }
  EXPECT_GT(moving, expected / 2);
  EXPECT_EQ(differ, moving);
}

TEST_F(VideoFromLog, SameLogSameVideo) {
  const LoadedLog log = load_log(*dir_ / "run.lcmlog");
  const std::vector<Pick> best = best_of_run(log.runs());
  const VideoSubject subject = make_video_subject(*best[0].run, *best[0].genome);
  VideoOptions o = small_video();
  o.speed = 8.0;
  Stage stage(o.encoder.width, o.encoder.height, o.samples);
  // Drawing and encoding on one thread, one frame after the other (how videos
  // were made before the two overlapped)...
  {
    VideoFrames frames(subject, o, stage);
    VideoEncoder encoder(*dir_ / "c.mp4", o.encoder);
    Image frame;
    while (frames.next(frame)) encoder.add_frame(frame);
    encoder.finish();
  }
  // ...gives the bytes that drawing and encoding side by side give, every time.
  render_video(subject, o, *dir_ / "a.mp4", {}, &stage);
  render_video(subject, o, *dir_ / "b.mp4", {}, &stage);
  auto bytes = [&](const char* name) {
    std::ifstream f(*dir_ / name, std::ios::binary);
    return std::string{std::istreambuf_iterator<char>(f), {}};
  };
  const std::string sa = bytes("a.mp4");
  EXPECT_GT(sa.size(), 1000u);
  EXPECT_EQ(sa, bytes("b.mp4"));
  EXPECT_EQ(sa, bytes("c.mp4"));
}

TEST(Video, FrameCountsAndOptions) {
  VideoOptions o;
  EXPECT_EQ(video_frame_count(25.0, o), 626);  // a 2,500-step champion at 25 fps, real time
  o.hold = 1.0;
  EXPECT_EQ(video_frame_count(25.0, o), 651);
  o.hold = 0;
  o.speed = 2;
  EXPECT_EQ(video_frame_count(25.0, o), 313);
  o.encoder.width = 1279;
  EXPECT_THROW(validate(o), std::invalid_argument);
  o = VideoOptions{};
  o.speed = 0;
  EXPECT_THROW(validate(o), std::invalid_argument);
}

}  // namespace
}  // namespace robozoo::render
