#include "render/bench.hpp"

#include <chrono>
#include <cstdio>
#include <stdexcept>
#include <unistd.h>

#include "runlog/log_source.hpp"
#include "runlog/selection.hpp"
#include "render/video_subject.hpp"

namespace robozoo::render {

namespace {
double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

BenchFigures run_bench(const BenchOptions& o) {
  validate(o.video);
  if (o.frames < 1) throw std::invalid_argument("bench: frames must be >= 1");
  const LoadedLog log = load_log(o.log);
  const std::vector<Pick> best = best_of_run(log.runs());
  if (best.empty()) throw std::runtime_error(o.log + ": no champion with a morphology");
  // The best champion that has a logged pose stream or can be re-simulated.
  Pick pick = best.front();
  for (const Pick& p : best)
    if (p.genome->genome.fitness > pick.genome->genome.fitness) pick = p;

  BenchFigures f;
  f.width = o.video.encoder.width;
  f.height = o.video.encoder.height;
  const auto ts = std::chrono::steady_clock::now();
  const VideoSubject subject = make_video_subject(*pick.run, *pick.genome);
  f.resimulated = subject.trajectory.resimulated;
  if (f.resimulated) f.resimulate_seconds = seconds_since(ts);
  f.spheres = static_cast<int>(subject.card.shape.size());
  f.video_steps = subject.trajectory.step.back() - subject.trajectory.step.front();
  f.video_sim_seconds = subject.trajectory.end_time() - subject.trajectory.start_time();

  Stage stage(f.width, f.height, o.video.samples);
  f.samples = stage.context().samples();
  f.renderer = stage.context().renderer();

  // Drawing: the first `frames` frames of the champion's video.
  std::vector<Image> frames;
  {
    VideoFrames vf(subject, o.video, stage);
    VideoStats s;
    Image img;
    for (int i = 0; i < o.frames; ++i) {
      if (!vf.next(img, &s)) break;
      frames.push_back(img);
    }
    f.draw_fps = frames.size() / s.draw_seconds;
    f.overlay_fps = s.overlay_seconds > 0 ? frames.size() / s.overlay_seconds : 0;
  }
  const std::string dir = o.scratch.empty() ? "/tmp" : o.scratch;
  const std::string path = dir + "/robozoo-render-bench-" + std::to_string(::getpid()) + ".mp4";
  // Encoding: the same frames again (RGB -> yuv420p, x264, MP4).
  {
    const auto t0 = std::chrono::steady_clock::now();
    VideoEncoder enc(path, o.video.encoder);
    for (int i = 0; i < o.frames; ++i) enc.add_frame(frames[static_cast<size_t>(i) % frames.size()]);
    enc.finish();
    f.encode_fps = o.frames / seconds_since(t0);
  }
  // The whole video, as `robozoo-render video` makes it (re-simulation included).
  {
    const auto t0 = std::chrono::steady_clock::now();
    const VideoSubject again = make_video_subject(*pick.run, *pick.genome);
    const VideoStats s = render_video(again, o.video, path, {}, &stage);
    f.video_wall_seconds = seconds_since(t0);
    f.video_frames = s.frames;
  }
  std::remove(path.c_str());
  return f;
}

void print(std::ostream& out, const BenchFigures& f) {
  char buf[512];
  std::snprintf(buf, sizeof buf,
                "renderer         %s\n"
                "size             %dx%d, %d samples per pixel, robot of %d spheres\n"
                "drawing          %.1f frames/s (scene + read-back)\n"
                "overlay          %.1f frames/s (text and panels alone)\n"
                "encoding         %.1f frames/s (yuv420p + H.264 + MP4)\n"
                "champion video   %d frames, %d steps = %.1f s simulated, made in %.1f s wall: %.2fx real time%s\n",
                f.renderer.c_str(), f.width, f.height, f.samples, f.spheres, f.draw_fps, f.overlay_fps, f.encode_fps,
                f.video_frames, f.video_steps, f.video_sim_seconds, f.video_wall_seconds,
                f.video_wall_seconds > 0 ? f.video_sim_seconds / f.video_wall_seconds : 0.0,
                f.resimulated ? " (re-simulated)" : "");
  out << buf;
}

}  // namespace robozoo::render
