#pragma once
// Reading a video back with libavformat/libavcodec, as a browser or ffprobe
// would: a file of one video stream, decoded on one thread, frame by frame.
// Used to measure an encoding's quality and by the video tests.
#include <functional>
#include <memory>
#include <string>

struct AVFrame;

namespace robozoo::render {

class VideoDecoder {
 public:
  /// Opens `path`; throws std::runtime_error when it cannot be opened, does not
  /// hold exactly one stream, or has no decoder.
  explicit VideoDecoder(const std::string& path);
  ~VideoDecoder();
  VideoDecoder(const VideoDecoder&) = delete;
  VideoDecoder& operator=(const VideoDecoder&) = delete;

  const std::string& codec() const { return codec_; }      ///< e.g. "h264"
  const std::string& pix_fmt() const { return pix_fmt_; }  ///< e.g. "yuv420p"
  int pix_fmt_id() const { return pix_fmt_id_; }           ///< libavutil's AVPixelFormat
  int width() const { return width_; }
  int height() const { return height_; }
  double fps() const { return fps_; }            ///< the stream's average frame rate
  double duration() const { return duration_; }  ///< the stream's duration (s) as ffprobe reports it; -1 if unknown

  /// Decodes every frame, in order (the decoder drained at the end), handing each
  /// to `take`; returns the number of frames decoded.
  int decode(const std::function<void(const AVFrame&)>& take);

 private:
  struct Context;
  std::unique_ptr<Context> c_;
  std::string path_, codec_, pix_fmt_;
  int pix_fmt_id_ = -1, width_ = 0, height_ = 0;
  double fps_ = 0, duration_ = -1;
};

}  // namespace robozoo::render
