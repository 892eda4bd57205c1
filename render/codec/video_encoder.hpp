#pragma once
// H.264 video files through libavcodec (libx264) and libavformat: yuv420p,
// MP4 with the index at the front (+faststart) so browsers can stream it, and
// bit-exact muxing so the same frames give the same file.
#include <memory>
#include <string>

#include "render/gl/image.hpp"

namespace robozoo::render {

struct EncoderOptions {
  int width = 1280;                 ///< (px, even)
  int height = 720;                 ///< (px, even)
  int fps = 25;                     ///< frames per second
  int crf = 23;                     ///< x264 constant rate factor (0-51, lower is better)
  std::string preset = "veryfast";  ///< x264 preset
  int threads = 1;                  ///< encoder threads; 0: libx264's choice, by the machine's cores
                                    ///< (its output depends on the thread count: 1 gives the same
                                    ///< bytes on every machine, and videos overlap drawing anyway)
};

/// Throws std::invalid_argument for odd or out-of-range sizes, a bad fps or crf.
void validate(const EncoderOptions& o);

/// libx264's preset of `robozoo-render video --fast`.
inline constexpr const char* kFastPreset = "superfast";

/// `--fast`: `o` with libx264's faster preset (kFastPreset) on libx264's own
/// thread count (threads 0, by the machine's cores). Faster and a larger file
/// at the same crf, and the bytes then depend on the machine.
EncoderOptions fast_encoder(EncoderOptions o);

class VideoEncoder {
 public:
  /// Opens `path` (.mp4) for writing. Throws std::invalid_argument for bad
  /// options, std::runtime_error when libav cannot (no libx264, unwritable path).
  VideoEncoder(const std::string& path, const EncoderOptions& options);
  ~VideoEncoder();
  VideoEncoder(const VideoEncoder&) = delete;
  VideoEncoder& operator=(const VideoEncoder&) = delete;

  /// Encodes the next frame; its size must be the video's.
  void add_frame(const Image& frame);
  /// Flushes the encoder and writes the file's index; the file is complete
  /// after this (the destructor of an unfinished encoder removes it).
  void finish();
  int frames() const { return frames_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  int frames_ = 0;
};

}  // namespace robozoo::render
