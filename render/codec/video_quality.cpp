#include "render/codec/video_quality.hpp"

#include "render/codec/video_decoder.hpp"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libswscale/swscale.h>
}

#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <stdexcept>

namespace robozoo::render {

namespace {

/// One plane, tightly packed.
struct Plane {
  int width = 0, height = 0;
  std::vector<uint8_t> px;
};

Plane copy_plane(const uint8_t* data, int linesize, int w, int h) {
  Plane p{w, h, std::vector<uint8_t>(static_cast<size_t>(w) * h)};
  for (int y = 0; y < h; ++y)
    std::copy(data + static_cast<long>(y) * linesize, data + static_cast<long>(y) * linesize + w,
              p.px.begin() + static_cast<long>(y) * w);
  return p;
}

double squared_error(const Plane& a, const Plane& b) {
  double s = 0;
  for (size_t i = 0; i < a.px.size(); ++i) {
    const double d = static_cast<double>(a.px[i]) - static_cast<double>(b.px[i]);
    s += d * d;
  }
  return s;
}

/// Sum of SSIM over 8x8 windows every 4 pixels, and the number of windows.
std::pair<double, long> ssim_sum(const Plane& a, const Plane& b) {
  constexpr double c1 = (0.01 * 255) * (0.01 * 255), c2 = (0.03 * 255) * (0.03 * 255);
  double sum = 0;
  long windows = 0;
  for (int y0 = 0; y0 + 8 <= a.height; y0 += 4)
    for (int x0 = 0; x0 + 8 <= a.width; x0 += 4) {
      double sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0;
      for (int y = y0; y < y0 + 8; ++y)
        for (int x = x0; x < x0 + 8; ++x) {
          const double va = a.px[static_cast<size_t>(y) * a.width + x], vb = b.px[static_cast<size_t>(y) * b.width + x];
          sa += va;
          sb += vb;
          saa += va * va;
          sbb += vb * vb;
          sab += va * vb;
        }
      const double n = 64, ma = sa / n, mb = sb / n;
      const double va = saa / n - ma * ma, vb = sbb / n - mb * mb, cov = sab / n - ma * mb;
      sum += ((2 * ma * mb + c1) * (2 * cov + c2)) / ((ma * ma + mb * mb + c1) * (va + vb + c2));
      ++windows;
    }
  return {sum, windows};
}

double psnr_of(double squared, double samples) {
  if (squared <= 0) return std::numeric_limits<double>::infinity();
  return 10.0 * std::log10(255.0 * 255.0 * samples / squared);
}

}  // namespace

VideoQuality measure_quality(const std::string& path, const std::vector<Image>& sources) {
  if (sources.empty()) throw std::invalid_argument("measure_quality: no source frames");
  const int w = sources.front().width(), h = sources.front().height();
  VideoDecoder video(path);
  AVFrame* source = av_frame_alloc();
  SwsContext* sws = nullptr;
  std::unique_ptr<void, std::function<void(void*)>> cleanup(reinterpret_cast<void*>(1), [&](void*) {
    sws_freeContext(sws);
    av_frame_free(&source);
  });
  if (!source) throw std::runtime_error("libav: out of memory");
  if (video.width() != w || video.height() != h || video.pix_fmt_id() != AV_PIX_FMT_YUV420P)
    throw std::runtime_error(path + ": not yuv420p of the sources' size");
  // The source frames as VideoEncoder converts them.
  sws = sws_getContext(w, h, AV_PIX_FMT_RGB24, w, h, AV_PIX_FMT_YUV420P, SWS_BICUBIC | SWS_ACCURATE_RND | SWS_BITEXACT,
                       nullptr, nullptr, nullptr);
  if (!sws) throw std::runtime_error("libswscale cannot convert RGB to yuv420p");
  const int* coeffs = sws_getCoefficients(SWS_CS_ITU709);
  sws_setColorspaceDetails(sws, coeffs, 1, coeffs, 0, 0, 1 << 16, 1 << 16);
  source->format = AV_PIX_FMT_YUV420P;
  source->width = w;
  source->height = h;
  if (av_frame_get_buffer(source, 0) < 0) throw std::runtime_error("libav: out of memory");

  VideoQuality q;
  double se[3] = {0, 0, 0}, ssim = 0;
  long windows = 0;
  video.decode([&](const AVFrame& frame) {
    const Image& img = sources[static_cast<size_t>(q.frames) % sources.size()];
    const uint8_t* src[1] = {img.bytes().data()};
    const int stride[1] = {3 * w};
    sws_scale(sws, src, stride, 0, h, source->data, source->linesize);
    for (int p = 0; p < 3; ++p) {
      const int pw = p == 0 ? w : w / 2, ph = p == 0 ? h : h / 2;
      const Plane a = copy_plane(frame.data[p], frame.linesize[p], pw, ph);
      const Plane b = copy_plane(source->data[p], source->linesize[p], pw, ph);
      se[p] += squared_error(a, b);
      if (p == 0) {
        const auto [s, n] = ssim_sum(a, b);
        ssim += s;
        windows += n;
      }
    }
    ++q.frames;
  });
  if (q.frames == 0) throw std::runtime_error(path + ": no frame decoded");
  const double luma = static_cast<double>(w) * h * q.frames, chroma = luma / 4;
  q.psnr_y = psnr_of(se[0], luma);
  q.psnr = psnr_of(se[0] + se[1] + se[2], luma + 2 * chroma);
  q.ssim_y = windows > 0 ? ssim / static_cast<double>(windows) : 1.0;
  return q;
}

}  // namespace robozoo::render
