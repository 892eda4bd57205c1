// robozoo-render: draws what evolution produced, headless (OSMesa/llvmpipe):
//   zoo    a PNG sheet of robots in their starting pose (the paper's Figure 4)
//   video  an H.264 MP4 of a champion moving
//   live   latest.png and one video per new champion, from an LCM bus
//   bench  frames per second of drawing and encoding
#include <signal.h>
#include <unistd.h>

#include <CLI/CLI.hpp>

extern "C" {
#include <libavutil/log.h>
}

#include <ctime>
#include <iostream>
#include <stdexcept>

#include "evolve/io/bus.hpp"
#include "render/bench.hpp"
#include "render/live.hpp"
#include "runlog/log_source.hpp"
#include "render/png_io.hpp"
#include "runlog/progress_bar.hpp"
#include "runlog/selection.hpp"
#include "render/video_subject.hpp"
#include "render/zoo_sheet.hpp"
#include "evolve/core/version.hpp"
#include "evolve/run/stop_signals.hpp"

using namespace robozoo;
using namespace robozoo::render;

namespace {

struct Size {
  int width = 0, height = 0;
};

/// "WxH" -> size; CLI11 check.
std::string parse_size(const std::string& s, Size& out) {
  int w = 0, h = 0;
  char x = 0, extra = 0;
  if (std::sscanf(s.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || (x != 'x' && x != 'X') || w <= 0 || h <= 0)
    return "expected WIDTHxHEIGHT, e.g. 1280x720, got '" + s + "'";
  out = {w, h};
  return "";
}

struct VideoArgs {
  std::string size = "1280x720";
  int fps = 25;
  double speed = 1.0;
  double hold = 0.0;
  int crf = 23;
  std::string preset = "veryfast";
  int threads = 1;
  int samples = 0;
  bool fast = false;
  bool no_overlay = false, no_grid = false;
  std::string font_dir;
  const CLI::Option* preset_option = nullptr;   // to tell a --preset given from the default
  const CLI::Option* threads_option = nullptr;
};

void add_video_options(CLI::App* app, VideoArgs& a) {
  app->add_option("--size", a.size, "video size WIDTHxHEIGHT, both even")->capture_default_str();
  app->add_option("--fps", a.fps, "frames per second")->capture_default_str();
  app->add_option("--speed", a.speed, "simulated seconds per second of video (1: real time)")->capture_default_str();
  app->add_option("--hold", a.hold, "show the last frame this many seconds longer")->capture_default_str();
  app->add_option("--crf", a.crf, "x264 quality, 0-51, lower is better")->capture_default_str();
  a.preset_option = app->add_option("--preset", a.preset, "x264 preset")->capture_default_str();
  a.threads_option = app->add_option("--threads", a.threads, "encoder threads; libx264's output depends on them: 1 gives the same bytes on every machine, 0 lets "
                  "libx264 choose by the machine's cores")->capture_default_str();
  app->add_flag("--fast", a.fast,
                std::string("faster encoding, other bytes: x264 preset ") + kFastPreset +
                    " on libx264's own thread count (--threads 0) instead of veryfast on one thread; a larger file at "
                    "the same --crf, and the output is no longer byte-reproducible across machines (it follows the "
                    "cores); not with --preset or --threads");
  app->add_option("--samples", a.samples, "multisampling, samples per pixel (0: none)")->capture_default_str();
  app->add_flag("--no-overlay", a.no_overlay, "no text over the picture");
  app->add_flag("--no-grid", a.no_grid, "no grid on the ground");
  app->add_option("--font-dir", a.font_dir, "folder with DejaVuSans.ttf and DejaVuSans-Bold.ttf");
}

VideoOptions video_options(const VideoArgs& a) {
  VideoOptions o;
  Size s;
  const std::string bad = parse_size(a.size, s);
  if (!bad.empty()) throw std::invalid_argument("--size: " + bad);
  o.encoder.width = s.width;
  o.encoder.height = s.height;
  o.encoder.fps = a.fps;
  o.encoder.crf = a.crf;
  o.encoder.preset = a.preset;
  o.encoder.threads = a.threads;
  if (a.fast) {
    if (a.preset_option->count() > 0 || a.threads_option->count() > 0)
      throw std::invalid_argument("--fast sets the x264 preset and threads itself: give --fast or --preset/--threads, not both");
    o.encoder = fast_encoder(o.encoder);
  }
  o.speed = a.speed;
  o.hold = a.hold;
  o.samples = a.samples;
  o.overlay = !a.no_overlay;
  o.grid = !a.no_grid;
  o.font_dir = a.font_dir;
  validate(o);
  return o;
}

void report_log(const LoadedLog& log) {
  if (log.collector->stats().rejected() > 0 || log.truncated) std::cerr << "robozoo-render: " << describe(log) << "\n";
}

// ---- zoo -------------------------------------------------------------------

struct ZooArgs {
  std::vector<std::string> logs;
  std::string out = "zoo.png";
  bool best_of_run = false;
  int top = 0;
  int generation = -1;
  std::string cell = "360x270";
  int columns = 0;
  std::string title;
  bool same_scale = false, no_grid = false, allow_truncated = false;
  int samples = 4;
  int font_size = 15;
  std::string font_dir;
};

int run_zoo(const ZooArgs& a) {
  ZooOptions o;
  Size cell;
  const std::string bad = parse_size(a.cell, cell);
  if (!bad.empty()) throw std::invalid_argument("--cell: " + bad);
  o.cell_width = cell.width;
  o.cell_height = cell.height;
  o.columns = a.columns;
  o.title = a.title;
  o.same_scale = a.same_scale;
  o.grid = !a.no_grid;
  o.samples = a.samples;
  o.font_size = a.font_size;
  o.font_dir = a.font_dir;
  validate(o);
  const int modes = (a.best_of_run ? 1 : 0) + (a.top > 0 ? 1 : 0) + (a.generation >= 0 ? 1 : 0);
  if (modes > 1) throw std::invalid_argument("choose one of --best-of-run, --top and --generation");

  LoadOptions lo;
  lo.allow_truncated = a.allow_truncated;
  lo.keep_poses = false;
  std::vector<LoadedLog> logs;
  std::vector<const RunRecord*> runs;
  for (const auto& path : a.logs) {
    logs.push_back(load_log(path, lo));
    report_log(logs.back());
    for (const RunRecord* r : logs.back().runs()) runs.push_back(r);
  }
  std::vector<Pick> picks;
  std::string what;
  if (a.generation >= 0) {
    picks = generation_champions(runs, a.generation);
    what = "a champion of generation " + std::to_string(a.generation);
  } else if (a.top > 0 || (!a.best_of_run && logs.size() == 1)) {
    if (logs.size() > 1) throw std::invalid_argument("--top takes one log (use --best-of-run for several)");
    picks = top_champions(runs, a.top > 0 ? a.top : 8);
    what = "a champion";
  } else {
    picks = best_of_run(runs);
    what = "a champion";
  }
  if (picks.empty()) throw std::runtime_error("no log holds " + what + " (ROBOZOO_GENOME with its ROBOZOO_MORPHOLOGY)");
  std::vector<RobotCard> cards;
  for (const Pick& p : picks) cards.push_back(make_card(*p.run, *p.genome));
  write_png(a.out, render_zoo(cards, o));
  std::cerr << "robozoo-render: " << a.out << " (" << cards.size() << " robots)\n";
  return 0;
}

// ---- video -----------------------------------------------------------------

struct VideoCmdArgs {
  std::string log;
  std::string out = "champion.mp4";
  int64_t genome = -1;
  int generation = -1;
  bool resimulate = false, allow_truncated = false, quiet = false;
  VideoArgs video;
};

int run_video(const VideoCmdArgs& a) {
  const VideoOptions o = video_options(a.video);
  LoadOptions lo;
  lo.allow_truncated = a.allow_truncated;
  const LoadedLog log = load_log(a.log, lo);
  report_log(log);
  std::vector<Pick> picks;
  if (a.genome >= 0) {
    picks = genome_by_id(log.runs(), a.genome);
    if (picks.empty())
      throw std::runtime_error(a.log + ": no genome " + std::to_string(a.genome) + " with a morphology");
  } else if (a.generation >= 0) {
    picks = generation_champions(log.runs(), a.generation);
    if (picks.empty()) throw std::runtime_error(a.log + ": no champion of generation " + std::to_string(a.generation));
  } else {
    picks = best_of_run(log.runs());
    if (picks.empty())
      throw std::runtime_error(a.log + ": no champion (ROBOZOO_GENOME with its ROBOZOO_MORPHOLOGY) in the log");
  }
  Pick pick = picks.front();
  for (const Pick& p : picks)
    if (p.genome->genome.fitness > pick.genome->genome.fitness) pick = p;
  VideoSubject subject = make_video_subject(*pick.run, *pick.genome, a.resimulate);
  const bool tty = ::isatty(2) && !a.quiet;
  const int frames = video_frame_count(subject.trajectory.end_time() - subject.trajectory.start_time(), o);
  ProgressBar bar(std::cerr, "rendering");
  const VideoStats s = render_video(subject, o, a.out, [&](int done, int) {
    if (tty) bar.update(done, frames);
  });
  bar.finish();
  if (!a.quiet)
    std::fprintf(stderr,
                 "robozoo-render: %s: genome %lld (generation %d, fitness %.3f), %d frames %dx%d, %.1f s simulated "
                 "in %.1f s (drawing %.1f s, overlay %.1f s, encoding %.1f s)%s\n",
                 a.out.c_str(), static_cast<long long>(subject.card.genome_id), subject.card.generation,
                 subject.card.fitness, s.frames, o.encoder.width, o.encoder.height,
                 subject.trajectory.end_time() - subject.trajectory.start_time(), s.total_seconds, s.draw_seconds,
                 s.overlay_seconds, s.encode_seconds, subject.trajectory.resimulated ? " (re-simulated: no poses in the log)" : "");
  return 0;
}

// ---- live ------------------------------------------------------------------

struct LiveArgs {
  std::string url = robozoo::kDefaultLcmUrl;
  std::string out;
  double stream_timeout = 3.0;
  double idle_exit = 0.0;
  std::string picture_size = "640x480";
  VideoArgs video;
};

int run_live_command(const LiveArgs& a) {
  LiveOptions o;
  o.url = a.url;
  o.out_dir = a.out;
  o.stream_timeout = a.stream_timeout;
  o.idle_exit = a.idle_exit;
  Size pic;
  const std::string bad = parse_size(a.picture_size, pic);
  if (!bad.empty()) throw std::invalid_argument("--picture-size: " + bad);
  o.picture.cell_width = pic.width;
  o.picture.cell_height = pic.height;
  o.picture.font_size = std::max(12, pic.height / 28);
  o.picture.font_dir = a.video.font_dir;
  o.video = video_options(a.video);
  validate(o);
  // SIGINT and SIGTERM end the loop cleanly: blocked here, before any thread
  // starts, and polled by the loop (no handler, no global flag).
  const std::function<bool()> should_stop = poll_interrupts();
  const LiveSummary s = run_live(o, should_stop, std::cerr);
  return s.failures > 0 ? 1 : 0;
}

// ---- bench -----------------------------------------------------------------

struct BenchArgs {
  std::string log;
  int frames = 100;
  VideoArgs video;
};

int run_bench_command(const BenchArgs& a) {
  if (a.video.fast)
    throw std::invalid_argument("bench measures the encoder settings given and --fast's side by side: leave out --fast");
  BenchOptions o;
  o.log = a.log;
  o.frames = a.frames;
  o.video = video_options(a.video);
  print(std::cout, run_bench(o));
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"robozoo-render: draws what robozoo-evolve produced, headless (OSMesa), from logs or live"};
  app.require_subcommand(1);

  ZooArgs zoo;
  CLI::App* zc = app.add_subcommand("zoo", "PNG sheet of robots in their starting pose (leaves red, others blue)");
  zc->add_option("logs", zoo.logs, "robozoo-evolve logs")->required();
  zc->add_option("-o,--output", zoo.out, "PNG to write")->capture_default_str();
  zc->add_flag("--best-of-run", zoo.best_of_run, "the best champion of each run (default with several logs)");
  zc->add_option("--top", zoo.top, "the N best distinct champions of one log (default with one log: 8)")
      ->check(CLI::Range(1, 10000));
  zc->add_option("--generation", zoo.generation, "the champion of generation G of each run")
      ->check(CLI::Range(0, 1000000000));
  zc->add_option("--cell", zoo.cell, "size of each robot's picture, WIDTHxHEIGHT")->capture_default_str();
  zc->add_option("--columns", zoo.columns, "robots per row (0: automatic)")->capture_default_str();
  zc->add_option("--title", zoo.title, "a title above the grid");
  zc->add_flag("--same-scale", zoo.same_scale, "one camera distance for all robots (sizes comparable)");
  zc->add_flag("--no-grid", zoo.no_grid, "no grid on the ground");
  zc->add_option("--samples", zoo.samples, "multisampling, samples per pixel (0: none)")->capture_default_str();
  zc->add_option("--font-size", zoo.font_size, "caption size in pixels")->capture_default_str();
  zc->add_option("--font-dir", zoo.font_dir, "folder with DejaVuSans.ttf and DejaVuSans-Bold.ttf");
  zc->add_flag("--allow-truncated", zoo.allow_truncated, "use the complete events of a log that ends mid-event");

  VideoCmdArgs video;
  CLI::App* vc = app.add_subcommand("video", "H.264 MP4 of a champion moving (from its logged poses)");
  vc->add_option("log", video.log, "robozoo-evolve log")->required();
  vc->add_option("-o,--output", video.out, "MP4 to write")->capture_default_str();
  vc->add_option("--genome", video.genome, "this genome instead of the run's best champion");
  vc->add_option("--generation", video.generation, "the champion of generation G instead of the best");
  vc->add_flag("--resimulate", video.resimulate, "ignore logged poses: re-simulate the genome");
  vc->add_flag("--allow-truncated", video.allow_truncated, "use the complete events of a log that ends mid-event");
  vc->add_flag("-q,--quiet", video.quiet, "no progress bar, no summary");
  add_video_options(vc, video.video);

  LiveArgs live;
  CLI::App* lc = app.add_subcommand("live", "latest.png and one video per new champion, from an LCM bus");
  lc->add_option("--lcm-url", live.url, "LCM URL to listen on (given alone: LCM's default URL)")
      ->expected(0, 1)
      ->capture_default_str();
  lc->add_option("--out", live.out, "output folder")->required();
  lc->add_option("--stream-timeout", live.stream_timeout, "seconds of silence that complete a pose stream")
      ->capture_default_str();
  lc->add_option("--idle-exit", live.idle_exit, "exit after this many seconds without messages (0: run until stopped)")
      ->capture_default_str();
  lc->add_option("--picture-size", live.picture_size, "size of latest.png's picture, WIDTHxHEIGHT")->capture_default_str();
  add_video_options(lc, live.video);

  BenchArgs bench;
  CLI::App* bc = app.add_subcommand("bench", "benchmark: drawing and encoding frames per second, one champion's video; "
                                    "the encoder settings given (default: the default's) against --fast's, same frames");
  bc->add_option("log", bench.log, "robozoo-evolve log (its best champion is drawn)")->required();
  bc->add_option("--frames", bench.frames, "frames timed")->capture_default_str()->check(CLI::Range(1, 100000));
  add_video_options(bc, bench.video);

  // libx264 and the MP4 muxer report every file on stderr; keep errors only.
  av_log_set_level(AV_LOG_ERROR);
  try {
    app.set_version_flag("--version", robozoo::version_line());
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  try {
    if (zc->parsed()) return run_zoo(zoo);
    if (vc->parsed()) return run_video(video);
    if (lc->parsed()) return run_live_command(live);
    if (bc->parsed()) return run_bench_command(bench);
  } catch (const std::invalid_argument& e) {
    std::cerr << "robozoo-render: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "robozoo-render: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
