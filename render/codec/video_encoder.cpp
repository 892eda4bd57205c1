#include "render/codec/video_encoder.hpp"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

#include <cstdio>
#include <stdexcept>
#include <string>

namespace robozoo::render {

namespace {

/// libx264's instruction sets, or "" for its own choice. Its AVX-512 kernels read memory
/// libx264 never wrote: on an AVX-512 machine the same frames gave other bytes whenever the
/// heap held other garbage (glibc's M_PERTURB showed it: QP 26.33 became 25.54-25.71). Its
/// assembly is otherwise bit-exact with its C code, so capping it at AVX2 there gives the
/// bytes of every other machine.
std::string x264_instruction_sets() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_cpu_init();
  if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx2")) return "AVX2";
#endif
  return "";
}
std::string av_error(int code) {
  char buf[AV_ERROR_MAX_STRING_SIZE] = {0};
  av_strerror(code, buf, sizeof buf);
  return buf;
}
}  // namespace

void validate(const EncoderOptions& o) {
  if (o.width < 16 || o.height < 16 || o.width > 8192 || o.height > 8192)
    throw std::invalid_argument("video size must be between 16x16 and 8192x8192, got " + std::to_string(o.width) + "x" +
                                std::to_string(o.height));
  if (o.width % 2 || o.height % 2)
    throw std::invalid_argument("video width and height must be even (yuv420p), got " + std::to_string(o.width) + "x" +
                                std::to_string(o.height));
  if (o.fps < 1 || o.fps > 240) throw std::invalid_argument("fps must be in [1, 240], got " + std::to_string(o.fps));
  if (o.crf < 0 || o.crf > 51) throw std::invalid_argument("crf must be in [0, 51], got " + std::to_string(o.crf));
  if (o.threads < 0 || o.threads > 64) throw std::invalid_argument("encoder threads must be in [0, 64]");
}

EncoderOptions fast_encoder(EncoderOptions o) {
  o.preset = kFastPreset;
  o.threads = 0;
  return o;
}

struct VideoEncoder::Impl {
  std::string path;     // the video
  std::string partial;  // written first, renamed to `path` when complete
  AVFormatContext* format = nullptr;
  AVCodecContext* codec = nullptr;
  AVStream* stream = nullptr;
  SwsContext* sws = nullptr;
  AVFrame* frame = nullptr;
  AVPacket* packet = nullptr;
  bool header_written = false;
  bool finished = false;

  ~Impl() {
    if (header_written && !finished) av_write_trailer(format);
    if (format && !(format->oformat->flags & AVFMT_NOFILE) && format->pb) avio_closep(&format->pb);
    avformat_free_context(format);
    avcodec_free_context(&codec);
    sws_freeContext(sws);
    av_frame_free(&frame);
    av_packet_free(&packet);
    if (!finished && !partial.empty()) std::remove(partial.c_str());
  }

  void drain(bool flushing) {
    for (;;) {
      const int r = avcodec_receive_packet(codec, packet);
      if (r == AVERROR(EAGAIN) || (flushing && r == AVERROR_EOF)) return;
      if (r < 0) throw std::runtime_error(path + ": encoding failed: " + av_error(r));
      av_packet_rescale_ts(packet, codec->time_base, stream->time_base);
      packet->stream_index = stream->index;
      const int w = av_interleaved_write_frame(format, packet);
      if (w < 0) throw std::runtime_error(path + ": writing failed: " + av_error(w));
    }
  }
};

VideoEncoder::VideoEncoder(const std::string& path, const EncoderOptions& o) : impl_(std::make_unique<Impl>()) {
  validate(o);
  Impl& m = *impl_;
  m.path = path;
  const std::string partial = path + ".part";
  int r = avformat_alloc_output_context2(&m.format, nullptr, "mp4", partial.c_str());
  if (r < 0 || !m.format) throw std::runtime_error(path + ": libavformat cannot write MP4: " + av_error(r));
  m.format->flags |= AVFMT_FLAG_BITEXACT;  // no library version strings: same frames, same bytes
  const AVCodec* x264 = avcodec_find_encoder_by_name("libx264");
  if (!x264) throw std::runtime_error("libavcodec has no libx264 encoder");
  m.stream = avformat_new_stream(m.format, nullptr);
  m.codec = avcodec_alloc_context3(x264);
  if (!m.stream || !m.codec) throw std::runtime_error("libav: out of memory");
  m.codec->width = o.width;
  m.codec->height = o.height;
  m.codec->time_base = AVRational{1, o.fps};
  m.codec->framerate = AVRational{o.fps, 1};
  m.codec->pix_fmt = AV_PIX_FMT_YUV420P;
  m.codec->gop_size = 2 * o.fps;
  m.codec->thread_count = o.threads;
  m.codec->color_range = AVCOL_RANGE_MPEG;
  m.codec->colorspace = AVCOL_SPC_BT709;
  m.codec->color_primaries = AVCOL_PRI_BT709;
  m.codec->color_trc = AVCOL_TRC_BT709;
  m.codec->flags |= AV_CODEC_FLAG_BITEXACT;
  if (m.format->oformat->flags & AVFMT_GLOBALHEADER) m.codec->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  AVDictionary* opts = nullptr;
  av_dict_set(&opts, "preset", o.preset.c_str(), 0);
  av_dict_set(&opts, "crf", std::to_string(o.crf).c_str(), 0);
  const std::string sets = x264_instruction_sets();
  if (!sets.empty()) av_dict_set(&opts, "x264-params", ("asm=" + sets).c_str(), 0);
  r = avcodec_open2(m.codec, x264, &opts);
  av_dict_free(&opts);
  if (r < 0) throw std::runtime_error("libx264 cannot start (preset '" + o.preset + "'?): " + av_error(r));
  r = avcodec_parameters_from_context(m.stream->codecpar, m.codec);
  if (r < 0) throw std::runtime_error("libav: " + av_error(r));
  m.stream->time_base = m.codec->time_base;
  m.stream->avg_frame_rate = m.codec->framerate;
  r = avio_open(&m.format->pb, partial.c_str(), AVIO_FLAG_WRITE);
  if (r < 0) throw std::runtime_error(path + ": cannot open for writing: " + av_error(r));
  m.partial = partial;  // from here on an unfinished file is removed
  AVDictionary* mux = nullptr;
  av_dict_set(&mux, "movflags", "+faststart", 0);
  r = avformat_write_header(m.format, &mux);
  av_dict_free(&mux);
  if (r < 0) throw std::runtime_error(path + ": cannot write the MP4 header: " + av_error(r));
  m.header_written = true;

  m.sws = sws_getContext(o.width, o.height, AV_PIX_FMT_RGB24, o.width, o.height, AV_PIX_FMT_YUV420P,
                         SWS_BICUBIC | SWS_ACCURATE_RND | SWS_BITEXACT, nullptr, nullptr, nullptr);
  if (!m.sws) throw std::runtime_error("libswscale cannot convert RGB to yuv420p");
  // BT.709 coefficients, limited range, to match the stream's tags.
  const int* coeffs = sws_getCoefficients(SWS_CS_ITU709);
  sws_setColorspaceDetails(m.sws, coeffs, 1, coeffs, 0, 0, 1 << 16, 1 << 16);
  m.frame = av_frame_alloc();
  m.packet = av_packet_alloc();
  if (!m.frame || !m.packet) throw std::runtime_error("libav: out of memory");
  m.frame->format = AV_PIX_FMT_YUV420P;
  m.frame->width = o.width;
  m.frame->height = o.height;
  r = av_frame_get_buffer(m.frame, 0);
  if (r < 0) throw std::runtime_error("libav: " + av_error(r));
}

VideoEncoder::~VideoEncoder() = default;

void VideoEncoder::add_frame(const Image& image) {
  Impl& m = *impl_;
  if (m.finished) throw std::logic_error("VideoEncoder::add_frame after finish");
  if (image.width() != m.codec->width || image.height() != m.codec->height)
    throw std::invalid_argument("frame is " + std::to_string(image.width()) + "x" + std::to_string(image.height()) +
                                ", the video " + std::to_string(m.codec->width) + "x" +
                                std::to_string(m.codec->height));
  const int r = av_frame_make_writable(m.frame);
  if (r < 0) throw std::runtime_error("libav: " + av_error(r));
  const uint8_t* src[1] = {image.bytes().data()};
  const int stride[1] = {3 * image.width()};
  sws_scale(m.sws, src, stride, 0, image.height(), m.frame->data, m.frame->linesize);
  m.frame->pts = frames_;
  const int s = avcodec_send_frame(m.codec, m.frame);
  if (s < 0) throw std::runtime_error(m.path + ": encoding failed: " + av_error(s));
  m.drain(false);
  ++frames_;
}

void VideoEncoder::finish() {
  Impl& m = *impl_;
  if (m.finished) return;
  const int s = avcodec_send_frame(m.codec, nullptr);
  if (s < 0) throw std::runtime_error(m.path + ": flushing the encoder failed: " + av_error(s));
  m.drain(true);
  const int r = av_write_trailer(m.format);
  if (r < 0) throw std::runtime_error(m.path + ": cannot write the MP4 index: " + av_error(r));
  avio_closep(&m.format->pb);
  if (std::rename(m.partial.c_str(), m.path.c_str()) != 0)
    throw std::runtime_error(m.path + ": cannot move the finished video into place");
  m.finished = true;
}

}  // namespace robozoo::render
