#include "render/video/bench.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <sched.h>
#include <time.h>
#include <unistd.h>

#include "evolve/core/wall_time.hpp"
#include "runlog/read/log_source.hpp"
#include "runlog/robots/selection.hpp"
#include "render/codec/video_quality.hpp"
#include "render/video/video_subject.hpp"

namespace robozoo::render {

namespace {
/// CPU time of every thread of this process: llvmpipe's and libx264's own threads included (s).
double process_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}
long long file_bytes(const std::string& path) {
  std::error_code ec;
  const auto n = std::filesystem::file_size(path, ec);
  if (ec) throw std::runtime_error(path + ": " + ec.message());
  return static_cast<long long>(n);
}
int usable_cores() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof set, &set) != 0) return 0;
  return CPU_COUNT(&set);
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
  f.cores = usable_cores();
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

  // Drawing: the first `frames` frames of the champion's video, each drawn
  // twice in turn: as videos draw it (background last) and with the
  // background drawn first under everything (the way before, the baseline).
  std::vector<Image> frames;
  {
    VideoFrames vf(subject, o.video, stage);
    VideoFrames before(subject, o.video, stage);
    VideoStats s, s_before;
    Image img, img_before;
    double cpu = 0, cpu_before = 0;
    for (int i = 0; i < o.frames; ++i) {
      stage.scene().set_background_last(false);
      double c0 = process_cpu_seconds();
      if (!before.next(img_before, &s_before)) break;
      cpu_before += process_cpu_seconds() - c0;
      stage.scene().set_background_last(true);
      c0 = process_cpu_seconds();
      if (!vf.next(img, &s)) break;
      cpu += process_cpu_seconds() - c0;
      if (img.bytes() != img_before.bytes()) ++f.frames_differing;
      frames.push_back(img);
    }
    f.drawn_frames = static_cast<int>(frames.size());
    f.draw_fps = frames.size() / s.draw_seconds;
    // (overlay included: a few percent of a frame's CPU time)
    f.draw_cpu_ms = 1e3 * cpu / static_cast<double>(frames.size());
    f.draw_cpu_ms_before = 1e3 * cpu_before / static_cast<double>(frames.size());
    f.overlay_fps = s.overlay_seconds > 0 ? frames.size() / s.overlay_seconds : 0;
  }
  const std::string dir = o.scratch.empty() ? "/tmp" : o.scratch;
  const std::string path = dir + "/robozoo-render-bench-" + std::to_string(::getpid()) + ".mp4";
  // Encoding: the same frames again (RGB -> yuv420p, x264, MP4), with the
  // settings given and with --fast's, each file then decoded and compared with
  // the frames.
  const EncoderOptions fast = fast_encoder(o.video.encoder);
  auto encode = [&](const EncoderOptions& e, BenchFigures::Encoding& r) {
    r.preset = e.preset;
    r.threads = e.threads;
    const auto t0 = std::chrono::steady_clock::now();
    const double c0 = process_cpu_seconds();
    VideoEncoder enc(path, e);
    for (int i = 0; i < o.frames; ++i) enc.add_frame(frames[static_cast<size_t>(i) % frames.size()]);
    enc.finish();
    r.wall_seconds = seconds_since(t0);
    r.cpu_ms = 1e3 * (process_cpu_seconds() - c0) / o.frames;
    r.bytes = file_bytes(path);
    const VideoQuality q = measure_quality(path, frames);
    if (q.frames != o.frames)
      throw std::runtime_error("bench: decoded " + std::to_string(q.frames) + " frames of " + std::to_string(o.frames));
    r.psnr_y = q.psnr_y;
    r.psnr = q.psnr;
    r.ssim_y = q.ssim_y;
  };
  f.encoded_frames = o.frames;
  encode(o.video.encoder, f.given);
  encode(fast, f.fast);
  f.encode_fps = o.frames / f.given.wall_seconds;
  f.encode_cpu_ms = f.given.cpu_ms;
  // The baseline, measured in the same run: the whole video drawn and encoded in
  // turn on one thread (how videos were made before the two overlapped; the same bytes).
  {
    const auto t0 = std::chrono::steady_clock::now();
    const double c0 = process_cpu_seconds();
    const VideoSubject again = make_video_subject(*pick.run, *pick.genome);
    VideoFrames vf(again, o.video, stage);
    VideoEncoder enc(path, o.video.encoder);
    Image img;
    while (vf.next(img)) enc.add_frame(img);
    enc.finish();
    f.serial_wall_seconds = seconds_since(t0);
    f.serial_cpu_seconds = process_cpu_seconds() - c0;
  }
  // The whole video, as `robozoo-render video` makes it (re-simulation included).
  {
    const auto t0 = std::chrono::steady_clock::now();
    const double c0 = process_cpu_seconds();
    const VideoSubject again = make_video_subject(*pick.run, *pick.genome);
    const VideoStats s = render_video(again, o.video, path, {}, &stage);
    f.video_wall_seconds = seconds_since(t0);
    f.video_cpu_seconds = process_cpu_seconds() - c0;
    f.video_frames = s.frames;
    f.video_bytes = file_bytes(path);
  }
  // The same with --fast's encoder.
  {
    VideoOptions v = o.video;
    v.encoder = fast;
    const auto t0 = std::chrono::steady_clock::now();
    const double c0 = process_cpu_seconds();
    const VideoSubject again = make_video_subject(*pick.run, *pick.genome);
    render_video(again, v, path, {}, &stage);
    f.fast_video_wall_seconds = seconds_since(t0);
    f.fast_video_cpu_seconds = process_cpu_seconds() - c0;
    f.fast_video_bytes = file_bytes(path);
  }
  std::remove(path.c_str());
  return f;
}

void print(std::ostream& out, const BenchFigures& f) {
  char buf[1536];
  const double n = f.video_frames > 0 ? f.video_frames : 1;
  std::snprintf(
      buf, sizeof buf,
      "renderer         %s\n"
      "size             %dx%d, %d samples per pixel, robot of %d spheres\n"
      "drawing          %.1f frames/s (scene + read-back), %.1f ms of CPU a frame; "
      "%.1f ms with the background drawn first (before), %d of %d frames differing\n"
      "overlay          %.1f frames/s (text and panels alone)\n"
      "encoding         %.1f frames/s (yuv420p + H.264 + MP4), %.1f ms of CPU a frame: "
      "%.1f s for the whole video on the encoding thread alone\n"
      "champion video   %d frames, %d steps = %.1f s simulated, made in %.1f s wall: %.2fx real time%s\n"
      "                 CPU %.1f s (%.1f ms a frame), %.2f of %d cores busy\n"
      "baseline         the same video drawn and encoded in turn: %.1f s wall, CPU %.1f s "
      "(%.2f cores busy); side by side is %.2fx faster\n",
      f.renderer.c_str(), f.width, f.height, f.samples, f.spheres, f.draw_fps, f.draw_cpu_ms, f.draw_cpu_ms_before,
      f.frames_differing, f.drawn_frames, f.overlay_fps, f.encode_fps, f.encode_cpu_ms,
      f.video_frames / (f.encode_fps > 0 ? f.encode_fps : 1.0), f.video_frames, f.video_steps, f.video_sim_seconds,
      f.video_wall_seconds, f.video_wall_seconds > 0 ? f.video_sim_seconds / f.video_wall_seconds : 0.0,
      f.resimulated ? " (re-simulated)" : "", f.video_cpu_seconds, 1e3 * f.video_cpu_seconds / n,
      f.video_wall_seconds > 0 ? f.video_cpu_seconds / f.video_wall_seconds : 0.0, f.cores, f.serial_wall_seconds,
      f.serial_cpu_seconds, f.serial_wall_seconds > 0 ? f.serial_cpu_seconds / f.serial_wall_seconds : 0.0,
      f.video_wall_seconds > 0 ? f.serial_wall_seconds / f.video_wall_seconds : 0.0);
  out << buf;
  const BenchFigures::Encoding& g = f.given;
  const BenchFigures::Encoding& q = f.fast;
  auto ratio = [](double a, double b) { return b > 0 ? a / b : 0.0; };
  auto threads = [](int t) {
    return t == 0 ? std::string("libx264's choice of threads") : std::to_string(t) + " thread" + (t == 1 ? "" : "s");
  };
  std::snprintf(buf, sizeof buf,
                "encoders         the %d timed frames encoded both ways, in turn:\n"
                "  default        %s, %s: %.2f s wall, %.1f ms of CPU a frame, %lld bytes, "
                "PSNR %.2f dB (luma %.2f), SSIM %.4f\n"
                "  --fast         %s, %s: %.2f s wall, %.1f ms of CPU a frame, %lld bytes, "
                "PSNR %.2f dB (luma %.2f), SSIM %.4f\n"
                "  fast/default   wall %.2fx, CPU %.2fx, size %.2fx, PSNR %+.2f dB, SSIM %+.4f\n"
                "fast video       the champion video with --fast side by side: %.1f s wall (default %.1f s: %.2fx), "
                "CPU %.1f s (%.1f ms a frame; default %.1f ms), %lld bytes (default %lld: %.2fx)\n",
                f.encoded_frames, g.preset.c_str(), threads(g.threads).c_str(), g.wall_seconds, g.cpu_ms, g.bytes,
                g.psnr, g.psnr_y, g.ssim_y, q.preset.c_str(), threads(q.threads).c_str(), q.wall_seconds, q.cpu_ms,
                q.bytes, q.psnr, q.psnr_y, q.ssim_y, ratio(q.wall_seconds, g.wall_seconds), ratio(q.cpu_ms, g.cpu_ms),
                ratio(static_cast<double>(q.bytes), static_cast<double>(g.bytes)), q.psnr - g.psnr, q.ssim_y - g.ssim_y,
                f.fast_video_wall_seconds, f.video_wall_seconds, ratio(f.fast_video_wall_seconds, f.video_wall_seconds),
                f.fast_video_cpu_seconds, 1e3 * f.fast_video_cpu_seconds / n, 1e3 * f.video_cpu_seconds / n,
                f.fast_video_bytes, f.video_bytes,
                ratio(static_cast<double>(f.fast_video_bytes), static_cast<double>(f.video_bytes)));
  out << buf;
}

}  // namespace robozoo::render
