#include "render/codec/video_quality.hpp"

#include <fcntl.h>  // tests/support/subprocess.hpp uses open()
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "render/codec/video_encoder.hpp"
#include "tests/support/subprocess.hpp"

namespace robozoo::render {
namespace {

using robozoo::testing::TempDir;

// Smooth gradients with a moving square: something for the encoder to lose.
std::vector<Image> frames(int w, int h, int n) {
  std::vector<Image> out;
  for (int i = 0; i < n; ++i) {
    Image img(w, h);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const bool square = x >= 4 * i && x < 4 * i + 16 && y >= 8 && y < 24;
        img.set(x, y,
                {static_cast<uint8_t>(square ? 250 : x * 2), static_cast<uint8_t>(y * 3 + i),
                 static_cast<uint8_t>(square ? 20 : 128)});
      }
    out.push_back(std::move(img));
  }
  return out;
}

std::string encode(const std::string& path, const std::vector<Image>& f, int crf) {
  EncoderOptions o;
  o.width = f.front().width();
  o.height = f.front().height();
  o.crf = crf;
  VideoEncoder enc(path, o);
  for (const Image& img : f) enc.add_frame(img);
  enc.finish();
  return path;
}

// crf 0 is lossless in libx264: the decoded frames are the converted sources,
// so PSNR is infinite and every SSIM window is exactly 1 (identical means and
// variances make numerator and denominator the same).
TEST(VideoQuality, LosslessIsIdentical) {
  TempDir dir;
  const std::vector<Image> f = frames(64, 48, 6);
  const VideoQuality q = measure_quality(encode(dir / "lossless.mp4", f, 0), f);
  EXPECT_EQ(q.frames, 6);
  EXPECT_TRUE(std::isinf(q.psnr_y));
  EXPECT_TRUE(std::isinf(q.psnr));
  EXPECT_NEAR(q.ssim_y, 1.0, 1e-12);
}

TEST(VideoQuality, CoarserQuantizerScoresLower) {
  TempDir dir;
  const std::vector<Image> f = frames(64, 48, 6);
  const VideoQuality fine = measure_quality(encode(dir / "fine.mp4", f, 18), f);
  const VideoQuality coarse = measure_quality(encode(dir / "coarse.mp4", f, 51), f);
  EXPECT_EQ(fine.frames, 6);
  EXPECT_EQ(coarse.frames, 6);
  EXPECT_TRUE(std::isfinite(fine.psnr_y));
  EXPECT_GT(fine.psnr_y, coarse.psnr_y + 3.0);
  EXPECT_GT(fine.psnr, coarse.psnr);
  EXPECT_GT(fine.ssim_y, coarse.ssim_y);
  EXPECT_LT(fine.ssim_y, 1.0);
  EXPECT_GT(coarse.ssim_y, 0.0);
}

TEST(VideoQuality, SourcesRepeatAndBadInputThrows) {
  TempDir dir;
  const std::vector<Image> f = frames(64, 48, 2);
  std::vector<Image> twice = f;
  twice.insert(twice.end(), f.begin(), f.end());
  const std::string path = encode(dir / "twice.mp4", twice, 0);
  // Four frames against two sources, taken in turn: still identical.
  const VideoQuality q = measure_quality(path, f);
  EXPECT_EQ(q.frames, 4);
  EXPECT_TRUE(std::isinf(q.psnr_y));
  EXPECT_THROW(measure_quality(path, frames(32, 48, 1)), std::runtime_error);  // another size
  EXPECT_THROW(measure_quality(dir / "none.mp4", f), std::runtime_error);
  std::ofstream(dir / "text.mp4") << "not a video";
  EXPECT_THROW(measure_quality(dir / "text.mp4", f), std::runtime_error);
  EXPECT_THROW(measure_quality(path, {}), std::invalid_argument);
}

}  // namespace
}  // namespace robozoo::render
