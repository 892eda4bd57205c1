#pragma once
// Behaviour videos: a robot moving along its trajectory at real time (by
// default), seen by a camera that follows it smoothly, over a ground grid for
// a sense of motion, with the target marked and an overlay saying who it is
// and the simulated time; encoded as H.264 MP4.
#include <functional>
#include <memory>
#include <string>

#include <Eigen/Core>

#include "render/gl/camera.hpp"
#include "render/scene/robot_card.hpp"
#include "render/scene/stage.hpp"
#include "render/gl/text.hpp"
#include "runlog/robots/trajectory.hpp"
#include "render/codec/video_encoder.hpp"

namespace robozoo::render {

struct VideoOptions {
  EncoderOptions encoder;                 ///< size (even), fps, crf, preset, threads
  double speed = 1.0;                     ///< simulated seconds per second of video (1: real time)
  double hold = 0.0;                      ///< the last frame is shown this much longer (s)
  int samples = 0;                        ///< multisampling (samples per pixel): llvmpipe's 4x costs ~3x the
                                          ///< drawing time; the outlines already smooth the silhouettes
  bool overlay = true;                    ///< run, generation, fitness and time over the picture
  bool grid = true;                       ///< grid lines on the ground
  ViewAngles angles{-105.0, 22.0, 30.0};  ///< the camera's direction: from the side, a little behind, so
                                          ///< a robot heading for the target (+x) moves to the right
  double zoom_out = 1.7;                  ///< camera distance over the one that just frames the starting pose
  double follow_smoothing = 0.8;          ///< follow camera's time constant (simulated s)
  int font_size = 0;                      ///< overlay text size (px); 0: height / 32
  std::string font_dir;                   ///< DejaVu fonts; empty: the system's
};

/// Throws std::invalid_argument for bad options (odd sizes, speed <= 0...).
void validate(const VideoOptions& o);

/// What a video shows.
struct VideoSubject {
  RobotCard card;
  Trajectory trajectory;
  Eigen::Vector3d target{50, 0, 0};  ///< where the robot should go (m)
};

/// Frames of a video of a trajectory lasting `duration` simulated seconds.
int video_frame_count(double duration, const VideoOptions& o);

struct VideoStats {
  int frames = 0;
  double draw_seconds = 0;     ///< drawing and reading back frames (s, wall, drawing thread)
  double overlay_seconds = 0;  ///< text and panels (s, wall, drawing thread)
  double encode_seconds = 0;   ///< colour conversion, encoding and writing (s, wall, encoding thread)
  double total_seconds = 0;    ///< (s, wall): less than the sum, as drawing and encoding overlap
};

/// Renders and encodes the video to `path`: the calling thread draws (with
/// `stage`'s GL context) while a second thread encodes, a few frames behind.
/// `progress(done, total)` is called on the calling thread after each frame is
/// drawn. `stage` (optional) is reused and resized.
VideoStats render_video(const VideoSubject& subject, const VideoOptions& options, const std::string& path,
                        const std::function<void(int, int)>& progress = {}, Stage* stage = nullptr);

/// The frames of a video, one after the other (the follow camera's state
/// carries from frame to frame); render_video encodes them, the benchmark
/// times them.
class VideoFrames {
 public:
  VideoFrames(const VideoSubject& subject, const VideoOptions& options, Stage& stage);
  int count() const { return count_; }
  /// Draws the next frame (0, 1, ...) into out; false when all are drawn.
  bool next(Image& out, VideoStats* stats = nullptr);

 private:
  const VideoSubject& subject_;
  VideoOptions options_;
  Stage& stage_;
  std::unique_ptr<FollowCamera> follow_;
  std::unique_ptr<Fonts> fonts_;
  std::unique_ptr<Font> legend_font_;
  double z_;  // height the camera aims at (m)
  int count_ = 0, index_ = 0;
};

}  // namespace robozoo::render
