#include "render/video/video.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <stdexcept>
#include <thread>

#include "evolve/core/wall_time.hpp"
#include "render/video/frame_queue.hpp"
#include "render/scene/overlay.hpp"

namespace robozoo::render {

namespace {
/// Frames drawn ahead of the encoder at most (2.7 MB each at 1280x720).
constexpr int kQueuedFrames = 4;

Eigen::Vector3d follow_point(const RobotShape& shape, const std::vector<Eigen::Vector3d>& centers) {
  return shape.mass_center(centers);
}
}  // namespace

void validate(const VideoOptions& o) {
  validate(o.encoder);
  if (!(o.speed > 0 && o.speed <= 1000)) throw std::invalid_argument("speed must be in (0, 1000]");
  if (!(o.hold >= 0 && o.hold <= 60)) throw std::invalid_argument("hold must be in [0, 60] s");
  if (!(o.zoom_out >= 1 && o.zoom_out <= 100)) throw std::invalid_argument("zoom-out must be in [1, 100]");
  if (!(o.follow_smoothing >= 0 && o.follow_smoothing <= 60))
    throw std::invalid_argument("follow smoothing must be in [0, 60] s");
  if (o.font_size != 0 && (o.font_size < 6 || o.font_size > 256))
    throw std::invalid_argument("font size must be 0 (automatic) or in [6, 256] pixels");
}

int video_frame_count(double duration, const VideoOptions& o) {
  const double moving = std::floor(std::max(0.0, duration) / o.speed * o.encoder.fps + 1e-9);
  return static_cast<int>(moving) + 1 + static_cast<int>(std::lround(o.hold * o.encoder.fps));
}

VideoFrames::VideoFrames(const VideoSubject& subject, const VideoOptions& options, Stage& stage)
    : subject_(subject), options_(options), stage_(stage) {
  validate(options_);
  if (subject_.trajectory.empty()) throw std::invalid_argument("the trajectory is empty");
  if (subject_.trajectory.centers.front().size() != subject_.card.shape.size())
    throw std::invalid_argument("the trajectory has " + std::to_string(subject_.trajectory.centers.front().size()) +
                                " spheres, the robot " + std::to_string(subject_.card.shape.size()));
  stage_.resize(options_.encoder.width, options_.encoder.height);
  const std::vector<Eigen::Vector3d>& first = subject_.trajectory.centers.front();
  Camera framing = frame_spheres(first, subject_.card.shape.radius, stage_.aspect(), options_.angles, 0.05);
  // Step back: room for the robot to move before the camera catches up.
  const Eigen::Vector3d offset = (framing.eye - framing.target) * options_.zoom_out;
  const double distance = offset.norm();
  const Eigen::Vector3d start = follow_point(subject_.card.shape, first);
  z_ = framing.target.z();
  framing.target = Eigen::Vector3d(start.x(), start.y(), z_);
  framing.eye = framing.target + offset;
  framing.near_m = std::max(1e-3, 0.05 * distance);
  framing.far_m = 40.0 * distance;
  follow_ = std::make_unique<FollowCamera>(framing, framing.target, options_.follow_smoothing);
  const int font = options_.font_size > 0 ? options_.font_size : std::max(10, options_.encoder.height / 32);
  if (options_.overlay) {
    fonts_ = std::make_unique<Fonts>(Fonts::load(font, options_.font_dir));
    legend_font_ = std::make_unique<Font>(font_path("DejaVuSans.ttf", options_.font_dir), std::max(8, font * 4 / 5));
  }
  count_ = video_frame_count(subject_.trajectory.end_time() - subject_.trajectory.start_time(), options_);
}

bool VideoFrames::next(Image& out, VideoStats* stats) {
  if (index_ >= count_) return false;
  const auto t0 = std::chrono::steady_clock::now();
  const Trajectory& tr = subject_.trajectory;
  const double dt = options_.speed / options_.encoder.fps;  // simulated seconds per frame
  const double t = std::min(tr.end_time(), tr.start_time() + index_ * dt);
  const std::vector<Eigen::Vector3d> centers = tr.sample(t);
  const Eigen::Vector3d com = follow_point(subject_.card.shape, centers);
  Eigen::Vector3d point = com;
  point.z() = z_;  // follow across the ground, not up and down
  const Camera& cam = follow_->update(point, index_ == 0 ? 0.0 : dt);

  SceneView view;
  view.spheres = subject_.card.shape.at(centers);
  view.grid = options_.grid;
  view.show_target = true;
  view.target = subject_.target;
  stage_.render(view, cam, out);
  const auto t1 = std::chrono::steady_clock::now();
  if (options_.overlay) {
    const RobotCard& c = subject_.card;
    OverlayText text;
    char buf[200];
    std::snprintf(buf, sizeof buf, "%s \u00b7 genome %lld", c.run_id.c_str(), static_cast<long long>(c.genome_id));
    text.title = buf;
    std::snprintf(buf, sizeof buf, "%s \u00b7 generation %d \u00b7 fitness %.2f", regime_label(c.regime).c_str(),
                  c.generation, c.fitness);
    text.lines.push_back(buf);
    std::snprintf(buf, sizeof buf, "t = %5.2f s of %.2f s", t, tr.end_time());
    std::string time_line = buf;
    if (options_.speed != 1.0) {
      std::snprintf(buf, sizeof buf, " \u00b7 played \u00d7%g", options_.speed);
      time_line += buf;
    }
    text.lines.push_back(time_line);
    std::snprintf(buf, sizeof buf, "centre of mass %.2f m from the target", (com - subject_.target).norm());
    text.lines.push_back(buf);
    if (tr.resimulated) text.lines.push_back("re-simulated (no poses in the log)");
    const double span = tr.end_time() - tr.start_time();
    text.progress = span > 0 ? (t - tr.start_time()) / span : 1.0;
    const int margin = std::max(8, options_.encoder.height / 40);
    draw_overlay(out, *fonts_, text, margin);
    draw_legend(out, *legend_font_, stage_.scene().style().leaf, stage_.scene().style().inner, margin);
    std::snprintf(buf, sizeof buf, "target %.1f m", (com - subject_.target).norm());
    draw_target_pointer(out, *legend_font_, project_to_pixel(cam, out.width(), out.height(), subject_.target), buf,
                        stage_.scene().style().target, margin);
  }
  if (stats) {
    stats->draw_seconds += std::chrono::duration<double>(t1 - t0).count();
    stats->overlay_seconds += seconds_since(t1);
  }
  ++index_;
  return true;
}

VideoStats render_video(const VideoSubject& subject, const VideoOptions& options, const std::string& path,
                        const std::function<void(int, int)>& progress, Stage* stage) {
  validate(options);
  const auto t0 = std::chrono::steady_clock::now();
  std::unique_ptr<Stage> own;
  if (!stage) {
    own = std::make_unique<Stage>(options.encoder.width, options.encoder.height, options.samples);
    stage = own.get();
  }
  VideoFrames frames(subject, options, *stage);
  VideoEncoder encoder(path, options.encoder);
  VideoStats stats;
  // This thread draws (it holds the GL context); another encodes, in frame
  // order, what the queue hands it: the encoder sees the same frames in the same
  // order as when one thread did both, so the file has the same bytes.
  FrameQueue queue(kQueuedFrames);
  std::exception_ptr encode_failure;
  double encode_seconds = 0;
  std::thread encoding([&] {
    try {
      Image frame;
      while (queue.pop(frame)) {
        const auto te = std::chrono::steady_clock::now();
        encoder.add_frame(frame);
        encode_seconds += seconds_since(te);
        queue.recycle(std::move(frame));
      }
    } catch (...) {
      encode_failure = std::current_exception();
      queue.abort();
    }
  });
  try {
    Image frame = queue.spare();
    while (frames.next(frame, &stats)) {
      if (!queue.push(std::move(frame))) break;  // the encoder failed
      ++stats.frames;
      if (progress) progress(stats.frames, frames.count());
      frame = queue.spare();
    }
    queue.close();
  } catch (...) {
    queue.abort();
    encoding.join();
    throw;
  }
  encoding.join();
  if (encode_failure) std::rethrow_exception(encode_failure);
  const auto te = std::chrono::steady_clock::now();
  encoder.finish();
  stats.encode_seconds = encode_seconds + seconds_since(te);
  stats.total_seconds = seconds_since(t0);
  return stats;
}

}  // namespace robozoo::render
