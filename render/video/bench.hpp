#pragma once
// Benchmark figures of robozoo-render: frames per second of drawing and of
// encoding, and the time to make one champion's whole video.
#include <ostream>
#include <string>

#include "render/video/video.hpp"

namespace robozoo::render {

struct BenchOptions {
  std::string log;      ///< a robozoo-evolve log; its best champion is drawn
  int frames = 100;     ///< frames timed for drawing and for encoding (count)
  VideoOptions video;   ///< size, samples, encoder settings
  std::string scratch;  ///< folder for the videos written; empty: /tmp
};

struct BenchFigures {
  int width = 0, height = 0, samples = 0;
  std::string renderer;            ///< GL_RENDERER
  int spheres = 0;                 ///< spheres of the robot drawn (count)
  double draw_fps = 0;             ///< drawing + read-back (frames/s)
  double overlay_fps = 0;          ///< text and panels alone (frames/s)
  double encode_fps = 0;           ///< RGB->yuv420p + x264 + MP4 (frames/s)
  int video_frames = 0;            ///< frames of the whole champion video (count)
  int video_steps = 0;             ///< physics steps it shows (count)
  double video_sim_seconds = 0;    ///< simulated time it shows (s)
  double video_wall_seconds = 0;   ///< wall time to make it (s), drawing and encoding side by side
  double video_cpu_seconds = 0;    ///< CPU time of every thread meanwhile (s)
  double serial_wall_seconds = 0;  ///< the same video drawn and encoded in turn on one thread (s): the baseline
  double serial_cpu_seconds = 0;   ///< CPU time of every thread meanwhile (s)
  double draw_cpu_ms = 0;          ///< CPU time per frame of drawing + read-back, every thread (ms)
  double draw_cpu_ms_before = 0;   ///< the same with the background drawn first, as before (ms): the baseline
  int drawn_frames = 0;            ///< frames drawn both ways (count)
  int frames_differing = 0;        ///< of those, frames whose pixels differ between the two ways (count; 0 expected)
  double encode_cpu_ms = 0;        ///< CPU time per frame of encoding, every thread (ms)
  /// Encoding the same timed frames with the settings given (the default) and with `--fast`'s
  /// (fast_encoder), one after the other in this run.
  struct Encoding {
    std::string preset;
    int threads = 0;              ///< libx264 threads asked for (0: its own choice)
    double wall_seconds = 0;      ///< (s)
    double cpu_ms = 0;            ///< CPU time per frame, every thread (ms)
    long long bytes = 0;          ///< the MP4's size (bytes)
    double psnr_y = 0, psnr = 0;  ///< against the source frames, luma and all planes (dB)
    double ssim_y = 0;            ///< against the source frames, luma (1: identical)
  };
  Encoding given, fast;
  int encoded_frames = 0;                           ///< frames encoded each way (count)
  double fast_video_wall_seconds = 0;               ///< the whole video side by side with `--fast`'s encoder (s)
  double fast_video_cpu_seconds = 0;                ///< CPU time of every thread meanwhile (s)
  long long video_bytes = 0, fast_video_bytes = 0;  ///< the whole video's MP4 both ways (bytes)
  int cores = 0;                                    ///< cores this process may run on (count)
  bool resimulated = false;                         ///< the trajectory had to be re-simulated
  double resimulate_seconds = 0;                    ///< time spent re-simulating (s)
};

/// Runs the benchmark; throws like load_log and render_video.
BenchFigures run_bench(const BenchOptions& options);
void print(std::ostream& out, const BenchFigures& f);

}  // namespace robozoo::render
