#pragma once
// Decoding a video in a test with libavformat/libavcodec: what a browser or
// ffprobe would see.
extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/pixdesc.h>
}

#include <cstdint>
#include <string>
#include <vector>

namespace robozoo::render::testing {

struct DecodedVideo {
  bool ok = false;
  std::string error;
  std::string codec;       ///< e.g. "h264"
  std::string pix_fmt;     ///< e.g. "yuv420p"
  int width = 0, height = 0;
  double fps = 0;
  double duration = 0;     ///< the stream's duration (s), as ffprobe reports it
  std::vector<std::vector<uint8_t>> luma;  ///< every frame's Y plane, width x height
  bool moov_before_mdat = false;           ///< +faststart
};

inline DecodedVideo decode_video(const std::string& path) {
  DecodedVideo v;
  AVFormatContext* fmt = nullptr;
  if (avformat_open_input(&fmt, path.c_str(), nullptr, nullptr) < 0) {
    v.error = "cannot open";
    return v;
  }
  AVCodecContext* dec = nullptr;
  AVPacket* pkt = av_packet_alloc();
  AVFrame* frame = av_frame_alloc();
  auto cleanup = [&] {
    av_frame_free(&frame);
    av_packet_free(&pkt);
    avcodec_free_context(&dec);
    avformat_close_input(&fmt);
  };
  if (avformat_find_stream_info(fmt, nullptr) < 0 || fmt->nb_streams != 1) {
    v.error = "no single stream";
    cleanup();
    return v;
  }
  AVStream* st = fmt->streams[0];
  const AVCodec* codec = avcodec_find_decoder(st->codecpar->codec_id);
  dec = avcodec_alloc_context3(codec);
  avcodec_parameters_to_context(dec, st->codecpar);
  dec->thread_count = 1;
  if (avcodec_open2(dec, codec, nullptr) < 0) {
    v.error = "cannot open decoder";
    cleanup();
    return v;
  }
  v.codec = codec->name;
  v.width = st->codecpar->width;
  v.height = st->codecpar->height;
  v.pix_fmt = av_get_pix_fmt_name(static_cast<AVPixelFormat>(st->codecpar->format));
  v.fps = av_q2d(st->avg_frame_rate);
  v.duration = st->duration != AV_NOPTS_VALUE ? st->duration * av_q2d(st->time_base) : -1;
  auto take = [&] {
    while (avcodec_receive_frame(dec, frame) == 0) {
      std::vector<uint8_t> y(static_cast<size_t>(frame->width) * frame->height);
      for (int r = 0; r < frame->height; ++r)
        std::copy(frame->data[0] + r * frame->linesize[0], frame->data[0] + r * frame->linesize[0] + frame->width,
                  y.begin() + static_cast<long>(r) * frame->width);
      v.luma.push_back(std::move(y));
    }
  };
  while (av_read_frame(fmt, pkt) >= 0) {
    avcodec_send_packet(dec, pkt);
    av_packet_unref(pkt);
    take();
  }
  avcodec_send_packet(dec, nullptr);
  take();
  cleanup();
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
