#pragma once
// Decoding a video in a test with libavformat/libavcodec: what a browser or
// ffprobe would see.
extern "C" {
#include <libavutil/frame.h>
}

#include <cstdint>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "render/codec/video_decoder.hpp"

namespace robozoo::render::testing {

struct DecodedVideo {
  bool ok = false;
  std::string error;
  std::string codec;    ///< e.g. "h264"
  std::string pix_fmt;  ///< e.g. "yuv420p"
  int width = 0, height = 0;
  double fps = 0;
  double duration = 0;                     ///< the stream's duration (s), as ffprobe reports it
  std::vector<std::vector<uint8_t>> luma;  ///< every frame's Y plane, width x height
  bool moov_before_mdat = false;           ///< +faststart
};

inline DecodedVideo decode_video(const std::string& path) {
  DecodedVideo v;
  try {
    VideoDecoder video(path);
    v.codec = video.codec();
    v.pix_fmt = video.pix_fmt();
    v.width = video.width();
    v.height = video.height();
    v.fps = video.fps();
    v.duration = video.duration();
    video.decode([&](const AVFrame& frame) {
      std::vector<uint8_t> y(static_cast<size_t>(frame.width) * frame.height);
      for (int r = 0; r < frame.height; ++r)
        std::copy(frame.data[0] + r * frame.linesize[0], frame.data[0] + r * frame.linesize[0] + frame.width,
                  y.begin() + static_cast<long>(r) * frame.width);
      v.luma.push_back(std::move(y));
    });
  } catch (const std::exception& e) {
    v.error = e.what();
    return v;
  }
  // +faststart: the 'moov' box comes before 'mdat'.
  FILE* f = std::fopen(path.c_str(), "rb");
  if (f) {
    std::vector<char> head(1 << 16);
    head.resize(std::fread(head.data(), 1, head.size(), f));
    std::fclose(f);
    const std::string s(head.begin(), head.end());
    const size_t moov = s.find("moov"), mdat = s.find("mdat");
    v.moov_before_mdat = moov != std::string::npos && (mdat == std::string::npos || moov < mdat);
  }
  v.ok = true;
  return v;
}

/// Mean absolute difference of two luma planes.
inline double luma_difference(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
  if (a.size() != b.size() || a.empty()) return -1;
  double s = 0;
  for (size_t i = 0; i < a.size(); ++i) s += std::abs(static_cast<int>(a[i]) - static_cast<int>(b[i]));
  return s / static_cast<double>(a.size());
}

}  // namespace robozoo::render::testing
