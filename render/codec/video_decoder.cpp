#include "render/codec/video_decoder.hpp"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/pixdesc.h>
}

#include <stdexcept>

namespace robozoo::render {

struct VideoDecoder::Context {
  AVFormatContext* fmt = nullptr;
  AVCodecContext* dec = nullptr;
  AVPacket* pkt = av_packet_alloc();
  AVFrame* frame = av_frame_alloc();
  ~Context() {
    av_frame_free(&frame);
    av_packet_free(&pkt);
    avcodec_free_context(&dec);
    avformat_close_input(&fmt);
  }
};

VideoDecoder::VideoDecoder(const std::string& path) : c_(std::make_unique<Context>()), path_(path) {
  if (!c_->pkt || !c_->frame) throw std::runtime_error("libav: out of memory");
  if (avformat_open_input(&c_->fmt, path.c_str(), nullptr, nullptr) < 0)
    throw std::runtime_error(path + ": cannot open");
  if (avformat_find_stream_info(c_->fmt, nullptr) < 0 || c_->fmt->nb_streams != 1)
    throw std::runtime_error(path + ": not a video of one stream");
  const AVStream* st = c_->fmt->streams[0];
  const AVCodec* codec = avcodec_find_decoder(st->codecpar->codec_id);
  if (!codec) throw std::runtime_error(path + ": no decoder");
  c_->dec = avcodec_alloc_context3(codec);
  if (!c_->dec) throw std::runtime_error("libav: out of memory");
  avcodec_parameters_to_context(c_->dec, st->codecpar);
  c_->dec->thread_count = 1;
  if (avcodec_open2(c_->dec, codec, nullptr) < 0) throw std::runtime_error(path + ": cannot open the decoder");
  codec_ = codec->name;
  width_ = st->codecpar->width;
  height_ = st->codecpar->height;
  pix_fmt_id_ = st->codecpar->format;
  const char* name = av_get_pix_fmt_name(static_cast<AVPixelFormat>(st->codecpar->format));
  pix_fmt_ = name ? name : "";
  fps_ = av_q2d(st->avg_frame_rate);
  duration_ = st->duration != AV_NOPTS_VALUE ? static_cast<double>(st->duration) * av_q2d(st->time_base) : -1;
}

VideoDecoder::~VideoDecoder() = default;

int VideoDecoder::decode(const std::function<void(const AVFrame&)>& take) {
  int frames = 0;
  auto drain = [&] {
    while (avcodec_receive_frame(c_->dec, c_->frame) == 0) {
      take(*c_->frame);
      ++frames;
    }
  };
  while (av_read_frame(c_->fmt, c_->pkt) >= 0) {
    avcodec_send_packet(c_->dec, c_->pkt);
    av_packet_unref(c_->pkt);
    drain();
  }
  avcodec_send_packet(c_->dec, nullptr);
  drain();
  return frames;
}

}  // namespace robozoo::render
