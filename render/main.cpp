// robozoo-render: draws what evolution produced, headless (OSMesa/llvmpipe):
//   zoo    a PNG sheet of robots in their starting pose (the paper's Figure 4)
//   video  an H.264 MP4 of a champion moving
// zoo and video draw from logs or from compact results (*.results.json, or a
// running experiment's folder of logs), whose best-of-run robots are grown and
// simulated again in memory, their fitness checked against the committed one
// first.
//   live   latest.png and one video per new champion, from an LCM bus
//   bench  frames per second of drawing and encoding
#include <signal.h>
#include <unistd.h>

#include <CLI/CLI.hpp>

extern "C" {
#include <libavutil/log.h>
}

#include <algorithm>
#include <chrono>
#include <ctime>
#include <iostream>
#include <stdexcept>
#include <thread>

#include "evolve/io/bus.hpp"
#include "render/video/bench.hpp"
#include "render/live/live.hpp"
#include "runlog/read/log_source.hpp"
#include "render/gl/png_io.hpp"
#include "runlog/progress_bar.hpp"
#include "runlog/robots/selection.hpp"
#include "render/video/video_subject.hpp"
#include "render/zoo/zoo_sheet.hpp"
#include "render/results/result_robots.hpp"
#include "evolve/core/version.hpp"
#include "util/exit_status.hpp"
#include "util/stop_signals.hpp"
#include "util/parse_options.hpp"

using namespace robozoo;
using namespace robozoo::render;

namespace {

/// Binds a "WxH" option to two size fields (px); its default is their values.
/// A malformed value throws std::invalid_argument naming the option.
CLI::Option* add_size_option(CLI::App* app, const std::string& name, int& width, int& height, const std::string& help) {
  return app
      ->add_option_function<std::string>(
          name,
          [name, &width, &height](const std::string& s) {
            int w = 0, h = 0;
            char x = 0, extra = 0;
            if (std::sscanf(s.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || (x != 'x' && x != 'X') || w <= 0 ||
                h <= 0)
              throw std::invalid_argument(name + ": expected WIDTHxHEIGHT, e.g. 1280x720, got '" + s + "'");
            width = w;
            height = h;
          },
          help)
      ->default_str(std::to_string(width) + "x" + std::to_string(height));
}

/// What the video options need besides VideoOptions' own fields: --fast, and
/// whether --preset or --threads were given (--fast refuses them).
struct FastFlag {
  bool fast = false;
  const CLI::Option* preset_option = nullptr;
  const CLI::Option* threads_option = nullptr;
};

void add_video_options(CLI::App* app, VideoOptions& o, FastFlag& f) {
  add_size_option(app, "--size", o.encoder.width, o.encoder.height, "video size WIDTHxHEIGHT, both even");
  app->add_option("--fps", o.encoder.fps, "frames per second")->capture_default_str();
  app->add_option("--speed", o.speed, "simulated seconds per second of video (1: real time)")->capture_default_str();
  app->add_option("--hold", o.hold, "show the last frame this many seconds longer")->capture_default_str();
  app->add_option("--crf", o.encoder.crf, "x264 quality, 0-51, lower is better")->capture_default_str();
  f.preset_option = app->add_option("--preset", o.encoder.preset, "x264 preset")->capture_default_str();
  f.threads_option =
      app->add_option(
             "--threads", o.encoder.threads,
             "encoder threads; libx264's output depends on them: 1 gives the same bytes on every machine, 0 lets "
             "libx264 choose by the machine's cores")
          ->capture_default_str();
  app->add_flag("--fast", f.fast,
                std::string("faster encoding, other bytes: x264 preset ") + kFastPreset +
                    " on libx264's own thread count (--threads 0) instead of veryfast on one thread; a larger file at "
                    "the same --crf, and the output is no longer byte-reproducible across machines (it follows the "
                    "cores); not with --preset or --threads");
  app->add_option("--samples", o.samples, "multisampling, samples per pixel (0: none)")->capture_default_str();
  app->add_flag_callback(
      "--no-overlay", [&o] { o.overlay = false; }, "no text over the picture");
  app->add_flag_callback(
      "--no-grid", [&o] { o.grid = false; }, "no grid on the ground");
  app->add_option("--font-dir", o.font_dir, "folder with DejaVuSans.ttf and DejaVuSans-Bold.ttf");
}

/// Applies --fast to the parsed options and checks them.
void finish_video_options(VideoOptions& o, const FastFlag& f) {
  if (f.fast) {
    if (f.preset_option->count() > 0 || f.threads_option->count() > 0)
      throw std::invalid_argument(
          "--fast sets the x264 preset and threads itself: give --fast or --preset/--threads, not both");
    o.encoder = fast_encoder(o.encoder);
  }
  validate(o);
}

/// Whether the inputs are compact results (true) or logs (false); refuses a mix.
bool inputs_are_results(const std::vector<std::string>& inputs) {
  size_t results = 0;
  for (const auto& p : inputs) results += is_results_path(p) ? 1 : 0;
  if (results > 0 && results < inputs.size())
    throw std::invalid_argument("give logs or compact results (*.results.json, folders of them), not both");
  return results > 0;
}

/// The compact results that `inputs` name, those that cannot be drawn yet (a
/// running trial's log before its first generation) left out with a note.
std::vector<RunResults> read_drawable_results(const std::vector<std::string>& inputs) {
  std::vector<std::string> left_out;
  std::vector<RunResults> all = read_results(results_files(inputs), &left_out);
  for (const std::string& why : left_out) std::cerr << "robozoo-render: left out " << why << "\n";
  if (all.empty()) throw std::runtime_error("no trial has a champion yet: nothing to draw");
  return all;
}

/// The best-of-run robots of compact results, re-grown and re-simulated in
/// memory, with a progress bar on a terminal and a line before and after.
std::vector<ResultRobot> replay_results(const std::vector<RunResults>& results, bool poses, int jobs, bool quiet) {
  const bool tty = ::isatty(2) && !quiet;
  const int at_once = std::min(static_cast<int>(results.size()),
                               jobs > 0 ? jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency())));
  if (!quiet)
    std::cerr << "robozoo-render: growing and simulating " << results.size() << " best-of-run robot"
              << (results.size() == 1 ? "" : "s") << " again, " << at_once
              << " at once, each checked against its committed fitness\n";
  const auto start = std::chrono::steady_clock::now();
  ProgressBar bar(std::cerr, "re-simulating");
  std::vector<ResultRobot> robots = result_robots(results, poses, at_once, [&](size_t done, size_t total) {
    if (tty) bar.update(static_cast<int64_t>(done), static_cast<int64_t>(total));
  });
  bar.finish();
  if (!quiet)
    std::fprintf(stderr, "robozoo-render: %zu %s committed fitness (%.1f s)\n", robots.size(),
                 robots.size() == 1 ? "robot reproduces its" : "robots reproduce their",
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  return robots;
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
  bool allow_truncated = false;
  int jobs = 0;
  bool quiet = false;
  ZooOptions sheet;
};

/// A zoo of compact results: every best-of-run robot, by arm and fitness.
int run_results_zoo(const ZooArgs& a) {
  if (a.top > 0 || a.generation >= 0)
    throw std::invalid_argument(
        "compact results hold one robot per trial, their best of run: no --top or --generation");
  if (a.allow_truncated) throw std::invalid_argument("--allow-truncated is for logs, not compact results");
  const std::vector<RunResults> all = read_drawable_results(a.logs);
  std::vector<RunResults> ordered;
  for (size_t i : figure_order(all)) ordered.push_back(all[i]);
  const std::vector<ResultRobot> robots = replay_results(ordered, false, a.jobs, a.quiet);
  std::vector<RobotCard> cards;
  for (const ResultRobot& r : robots) cards.push_back(result_card(r));
  write_png(a.out, render_zoo(cards, a.sheet));
  std::cerr << "robozoo-render: " << a.out << " (" << cards.size() << " robots)\n";
  return 0;
}

int run_zoo(const ZooArgs& a) {
  validate(a.sheet);
  if (a.jobs < 0) throw std::invalid_argument("--jobs must be 0 (one per core) or more");
  if (inputs_are_results(a.logs)) return run_results_zoo(a);
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
  write_png(a.out, render_zoo(cards, a.sheet));
  std::cerr << "robozoo-render: " << a.out << " (" << cards.size() << " robots)\n";
  return 0;
}

// ---- video -----------------------------------------------------------------

struct VideoCmdArgs {
  std::vector<std::string> inputs;
  std::string pick;
  std::string out = "champion.mp4";
  int64_t genome = -1;
  int generation = -1;
  bool resimulate = false, allow_truncated = false, quiet = false;
  VideoOptions video;
  FastFlag fast;
};

/// The video's robot from compact results: the one `pick` names among them,
/// re-grown and re-simulated (its fitness checked first).
VideoSubject results_video_subject(const VideoCmdArgs& a) {
  if (a.genome >= 0 || a.generation >= 0 || a.resimulate || a.allow_truncated)
    throw std::invalid_argument(
        "compact results hold one robot per trial, re-simulated anyway: no --genome, --generation, --resimulate or "
        "--allow-truncated (choose among several with --pick)");
  const std::vector<RunResults> all = read_drawable_results(a.inputs);
  const RunResults& chosen = all[pick_result(all, a.pick.empty() ? "best" : a.pick)];
  if (!a.quiet && all.size() > 1)
    std::cerr << "robozoo-render: " << (a.pick.empty() ? "best" : a.pick) << " of " << all.size()
              << " best-of-run robots by committed fitness: " << chosen.run.run_id << " (" << chosen.run.path << ")\n";
  const std::vector<ResultRobot> robots = replay_results({chosen}, true, 1, a.quiet);
  const ResultRobot& r = robots.front();
  return make_video_subject(r.record, r.champion());
}

/// The video's robot from a log: the genome, the champion of a generation, or
/// the best champion of the log.
VideoSubject log_video_subject(const VideoCmdArgs& a) {
  if (!a.pick.empty()) throw std::invalid_argument("--pick chooses among compact results; with a log, use --genome");
  if (a.inputs.size() != 1) throw std::invalid_argument("video takes one log");
  const std::string& path = a.inputs.front();
  LoadOptions lo;
  lo.allow_truncated = a.allow_truncated;
  const LoadedLog log = load_log(path, lo);
  report_log(log);
  std::vector<Pick> picks;
  if (a.genome >= 0) {
    picks = genome_by_id(log.runs(), a.genome);
    if (picks.empty())
      throw std::runtime_error(path + ": no genome " + std::to_string(a.genome) + " with a morphology");
  } else if (a.generation >= 0) {
    picks = generation_champions(log.runs(), a.generation);
    if (picks.empty()) throw std::runtime_error(path + ": no champion of generation " + std::to_string(a.generation));
  } else {
    picks = best_of_run(log.runs());
    if (picks.empty())
      throw std::runtime_error(path + ": no champion (ROBOZOO_GENOME with its ROBOZOO_MORPHOLOGY) in the log");
  }
  Pick pick = picks.front();
  for (const Pick& p : picks)
    if (p.genome->genome.fitness > pick.genome->genome.fitness) pick = p;
  return make_video_subject(*pick.run, *pick.genome, a.resimulate);
}

int run_video(VideoCmdArgs& a) {
  finish_video_options(a.video, a.fast);
  const VideoOptions& o = a.video;
  VideoSubject subject;
  if (inputs_are_results(a.inputs))
    subject = results_video_subject(a);
  else
    subject = log_video_subject(a);
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
                 s.overlay_seconds, s.encode_seconds,
                 subject.trajectory.resimulated ? " (re-simulated: no poses in the log)" : "");
  return 0;
}

// ---- live ------------------------------------------------------------------

struct LiveArgs {
  LiveOptions options;
  FastFlag fast;
};

int run_live_command(LiveArgs& a) {
  LiveOptions& o = a.options;
  o.picture.font_size = std::max(12, o.picture.cell_height / 28);
  o.picture.font_dir = o.video.font_dir;
  finish_video_options(o.video, a.fast);
  validate(o);
  // SIGINT and SIGTERM end the loop cleanly: blocked here, before any thread
  // starts, and polled by the loop (no handler, no global flag).
  const std::function<bool()> should_stop = poll_interrupts();
  const LiveSummary s = run_live(o, should_stop, std::cerr);
  return s.failures > 0 ? 1 : 0;
}

// ---- bench -----------------------------------------------------------------

struct BenchArgs {
  BenchOptions options;
  FastFlag fast;
};

int run_bench_command(BenchArgs& a) {
  if (a.fast.fast)
    throw std::invalid_argument(
        "bench measures the encoder settings given and --fast's side by side: leave out --fast");
  BenchOptions& o = a.options;
  finish_video_options(o.video, a.fast);
  print(std::cout, run_bench(o));
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"robozoo-render: draws what robozoo-evolve produced, headless (OSMesa), from logs or live"};
  app.require_subcommand(1);

  ZooArgs zoo;
  CLI::App* zc = app.add_subcommand("zoo", "PNG sheet of robots in their starting pose (leaves red, others blue)");
  zc->add_option("inputs", zoo.logs,
                 "robozoo-evolve logs, or compact results: *.results.json files, *.portable-checkpoint files (a "
                 "trial in progress: its champion so far) or folders of them (each trial's best-of-run robot, grown "
                 "and simulated again, its fitness checked; ordered by arm and fitness); a folder of logs alone (a "
                 "running experiment's) is drawn the same way, each log read as its trial's result so far")
      ->required();
  zc->add_option("-o,--output", zoo.out, "PNG to write")->capture_default_str();
  zc->add_flag("--best-of-run", zoo.best_of_run, "the best champion of each run (default with several logs)");
  zc->add_option("--top", zoo.top, "the N best distinct champions of one log (default with one log: 8)")
      ->check(CLI::Range(1, 10000));
  zc->add_option("--generation", zoo.generation, "the champion of generation G of each run")
      ->check(CLI::Range(0, 1000000000));
  add_size_option(zc, "--cell", zoo.sheet.cell_width, zoo.sheet.cell_height,
                  "size of each robot's picture, WIDTHxHEIGHT");
  zc->add_option("--columns", zoo.sheet.columns, "robots per row (0: automatic)")->capture_default_str();
  zc->add_option("--title", zoo.sheet.title, "a title above the grid");
  zc->add_flag("--same-scale", zoo.sheet.same_scale, "one camera distance for all robots (sizes comparable)");
  zc->add_option("--inset-below", zoo.sheet.inset_below,
                 "--same-scale: a robot drawn at less than this fraction of the size that fills its cell also gets an "
                 "inset that it fills, marked with its magnification (0: none)")
      ->capture_default_str();
  zc->add_flag_callback(
      "--no-grid", [&zoo] { zoo.sheet.grid = false; }, "no grid on the ground");
  zc->add_option("--samples", zoo.sheet.samples, "multisampling, samples per pixel (0: none)")->capture_default_str();
  zc->add_option("--font-size", zoo.sheet.font_size, "caption size in pixels")->capture_default_str();
  zc->add_option("--font-dir", zoo.sheet.font_dir, "folder with DejaVuSans.ttf and DejaVuSans-Bold.ttf");
  zc->add_flag("--allow-truncated", zoo.allow_truncated, "use the complete events of a log that ends mid-event");
  zc->add_option("-j,--jobs", zoo.jobs,
                 "compact results: robots simulated at once (0: one per core); the same sheet for any number")
      ->capture_default_str();
  zc->add_flag("-q,--quiet", zoo.quiet, "compact results: no progress bar, no report of the re-simulation");

  VideoCmdArgs video;
  CLI::App* vc = app.add_subcommand(
      "video", "H.264 MP4 of a champion moving (from its logged poses, or re-simulated from a compact result)");
  vc->add_option("input", video.inputs,
                 "a robozoo-evolve log, or compact results: *.results.json files, *.portable-checkpoint files or "
                 "folders of them, or a running experiment's folder of logs (the --pick trial's best-of-run robot, "
                 "grown and simulated again, its fitness checked)")
      ->required();
  vc->add_option("--pick", video.pick,
                 "compact results: whose robot, by committed best-of-run fitness: best, median (rank ceil(n/2) of n, "
                 "best first) or worst (default: best)")
      ->check(CLI::IsMember({"best", "median", "worst"}));
  vc->add_option("-o,--output", video.out, "MP4 to write")->capture_default_str();
  vc->add_option("--genome", video.genome, "this genome instead of the run's best champion");
  vc->add_option("--generation", video.generation, "the champion of generation G instead of the best");
  vc->add_flag("--resimulate", video.resimulate, "ignore logged poses: re-simulate the genome");
  vc->add_flag("--allow-truncated", video.allow_truncated, "use the complete events of a log that ends mid-event");
  vc->add_flag("-q,--quiet", video.quiet, "no progress bar, no summary");
  add_video_options(vc, video.video, video.fast);

  LiveArgs live_args;
  LiveOptions& live = live_args.options;
  live.url = robozoo::kDefaultLcmUrl;
  live.picture.cell_width = 640;
  live.picture.cell_height = 480;
  CLI::App* lc = app.add_subcommand("live", "latest.png and one video per new champion, from an LCM bus");
  lc->add_option("--lcm-url", live.url, "LCM URL to listen on (given alone: LCM's default URL)")
      ->expected(0, 1)
      ->capture_default_str();
  lc->add_option("--out", live.out_dir, "output folder")->required();
  lc->add_option("--stream-timeout", live.stream_timeout, "seconds of silence that complete a pose stream")
      ->capture_default_str();
  lc->add_option("--idle-exit", live.idle_exit, "exit after this many seconds without messages (0: run until stopped)")
      ->capture_default_str();
  add_size_option(lc, "--picture-size", live.picture.cell_width, live.picture.cell_height,
                  "size of latest.png's picture, WIDTHxHEIGHT");
  add_video_options(lc, live.video, live_args.fast);

  BenchArgs bench;
  CLI::App* bc =
      app.add_subcommand("bench",
                         "benchmark: drawing and encoding frames per second, one champion's video; "
                         "the encoder settings given (default: the default's) against --fast's, same frames");
  bc->add_option("log", bench.options.log, "robozoo-evolve log (its best champion is drawn)")->required();
  bc->add_option("--frames", bench.options.frames, "frames timed")->capture_default_str()->check(CLI::Range(1, 100000));
  add_video_options(bc, bench.options.video, bench.fast);

  // libx264 and the MP4 muxer report every file on stderr; keep errors only.
  av_log_set_level(AV_LOG_ERROR);
  return robozoo::exit_status_of("robozoo-render", [&] {
    app.set_version_flag("--version", robozoo::version_line());
    if (const auto stop = robozoo::parse_options(app, argc, argv, "robozoo-render")) return *stop;
    if (zc->parsed()) return run_zoo(zoo);
    if (vc->parsed()) return run_video(video);
    if (lc->parsed()) return run_live_command(live_args);
    if (bc->parsed()) return run_bench_command(bench);
    return 0;
  });
}
