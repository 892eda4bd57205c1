// robozoo-view: watch a run in the browser, live from the bus or played from a
// log. One page on http://127.0.0.1:8080, fed over a WebSocket.
#include <signal.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iomanip>
#include <thread>
#include <iostream>
#include <memory>
#include <regex>

#include "evolve/core/version.hpp"
#include "evolve/io/bus.hpp"
#include "view/serve/assets.hpp"
#include "view/feed/bus_feed.hpp"
#include "view/feed/experiment_watch.hpp"
#include "view/replays/trial_page.hpp"
#include "view/replays/zoo_strip.hpp"
#include "util/exit_status.hpp"
#include "view/replays/export.hpp"
#include "view/feed/log_feed.hpp"
#include "view/serve/server.hpp"
#include "view/state/view_state.hpp"
#include "util/stop_signals.hpp"
#include "util/parse_options.hpp"

namespace {

using namespace robozoo;
using namespace robozoo::view;

struct Args {
  std::string lcm_url;
  LogFeedOptions log;
  ServerOptions server;
  ViewStateOptions state;
  BusFeedOptions bus;
  AssetDirs dirs;
  bool quiet = false;
  ExportOptions export_options;
  int64_t export_genome = -1;
  std::string export_out;
  std::string experiment;
  ExperimentWatchOptions watch;
  double poll_seconds = 2.0;
};

void fill_dirs(AssetDirs& dirs) {
  const AssetDirs defaults = default_asset_dirs();
  if (dirs.page.empty()) dirs.page = defaults.page;
  if (dirs.three.empty()) dirs.three = defaults.three;
}

/// robozoo-view export LOG [--genome N] -o OUT.html
int run_export(CLI::App& sub, Args& a) {
  fill_dirs(a.dirs);
  if (sub.count("--genome")) a.export_options.genome = a.export_genome;
  const nlohmann::json frames = champion_frames(a.export_options);
  const std::string html = offline_page(a.dirs, frames);
  write_whole_file(a.export_out, html);
  const nlohmann::json& robot = frames[4];
  std::cerr << "robozoo-view: wrote " << a.export_out << ": genome " << robot["id"] << " (generation " << robot["gen"]
            << ", " << robot["radius"].size() << " spheres, " << frames[5]["list"].size() << " samples), " << std::fixed
            << std::setprecision(2) << html.size() / 1e6 << " MB\n";
  return 0;
}

/// GET /export?genome=N in log mode: the one-file replay as a download.
Route export_route(const std::string& log, const AssetDirs& dirs) {
  return [log, dirs](const std::string& target) -> std::optional<HttpReply> {
    static const std::regex re(R"(/export(\?genome=(-?[0-9]{1,18}))?)");
    std::smatch m;
    if (!std::regex_match(target, m, re)) return std::nullopt;
    if (log.empty()) return HttpReply{409, "text/plain; charset=utf-8", "export needs a log: robozoo-view LOG\n", ""};
    ExportOptions o;
    o.log = log;
    o.allow_truncated = true;  // --follow: the log may end inside its newest event
    if (m[2].matched) o.genome = std::stoll(m[2].str());
    try {
      const nlohmann::json frames = champion_frames(o);
      return HttpReply{200, "text/html; charset=utf-8", offline_page(dirs, frames),
                       "champion-" + frames[4]["id"].dump() + ".html"};
    } catch (const std::exception& e) {
      return HttpReply{404, "text/plain; charset=utf-8", std::string(e.what()) + "\n", ""};
    }
  };
}

std::string address_text(const std::string& bind, unsigned short port) {
  const std::string host = bind.find(':') != std::string::npos ? "[" + bind + "]"
                           : bind == "0.0.0.0"                 ? "127.0.0.1"
                                                               : bind;
  return "http://" + host + ":" + std::to_string(port) + "/";
}

int run_experiment(Args& a);

int run(CLI::App& app, Args& a) {
  const bool live = app.count("--lcm-url") > 0;
  if (!a.experiment.empty()) {
    if (live || !a.log.path.empty()) {
      std::cerr << "robozoo-view: give one of --lcm-url [URL], a LOG or --experiment DIR\n";
      return 2;
    }
    return run_experiment(a);
  }
  if (app.count("--poll") || app.count("--running-seconds") || app.count("--results")) {
    std::cerr << "robozoo-view: --poll, --running-seconds and --results are for --experiment\n";
    return 2;
  }
  if (live == !a.log.path.empty()) {
    std::cerr << "robozoo-view: give either --lcm-url [URL] or a LOG\n" << app.help();
    return 2;
  }
  if (live && (app.count("--speed") || app.count("--loop") || app.count("--generation") || app.count("--follow") ||
               app.count("--exit-at-end"))) {
    std::cerr << "robozoo-view: --speed, --loop, --generation, --follow and --exit-at-end are for a LOG\n";
    return 2;
  }
  if (!live && app.count("--idle-exit")) {
    std::cerr << "robozoo-view: --idle-exit is for --lcm-url\n";
    return 2;
  }
  if (a.log.loop && a.log.follow) {
    std::cerr << "robozoo-view: --loop and --follow exclude each other\n";
    return 2;
  }
  if (live) a.bus.url = a.lcm_url.empty() ? kDefaultLcmUrl : a.lcm_url;
  fill_dirs(a.dirs);
  a.server.route = export_route(live ? "" : a.log.path, a.dirs);

  // SIGINT and SIGTERM end the loop cleanly: blocked here, before any thread
  // starts, and polled by the loop (no handler, no global flag).
  const std::function<bool()> should_stop = poll_interrupts();

  const AssetTable assets = AssetTable::load(a.dirs);
  if (!live) a.state.keep_streams = 0;  // a log is in memory anyway: every replay from its poses
  ViewState state(live ? "live" : "log", live ? a.bus.url : a.log.path, a.state);
  Server server(a.server, assets, state);
  server.start();
  std::cerr << "robozoo-view: open " << address_text(a.server.bind, server.port()) << std::endl;
  std::ostream silent(nullptr);
  std::ostream& log = a.quiet ? silent : std::cerr;
  if (live)
    follow_bus(a.bus, state, should_stop, log);
  else
    play_log(a.log, state, should_stop, log);
  const ViewCounters c = state.counters();
  server.stop();
  std::cerr << "robozoo-view: " << c.messages << " messages (" << c.bad << " bad, skipped), run "
            << (c.run_id.empty() ? "-" : c.run_id) << ", " << c.generations << " generations, " << c.champions
            << " champions, " << c.poses << " poses, " << c.dropped_poses << " poses dropped for slow pages, "
            << c.pages_given_up << " pages given up, " << server.refused() << " requests refused\n";
  return 0;
}

/// --experiment: /experiment.json (the summary), /trial?name=T (that
/// trial's champion as a one-file replay, shown in the browser: trial_page)
/// and /zoo.json (the thumbnail strips' robots: ZooStrips).
Route experiment_route(const ExperimentWatch& watch, const AssetDirs& dirs) {
  auto zoo = std::make_shared<ZooStrips>();
  return [&watch, dirs, zoo](const std::string& target) -> std::optional<HttpReply> {
    if (target == "/experiment.json") return HttpReply{200, "application/json", watch.summary(), ""};
    if (target == "/zoo.json") return HttpReply{200, "application/json", zoo->json(watch), ""};
    static const std::regex re(R"(/trial\?name=([a-z-]+-s[0-9]{1,18}))");
    std::smatch m;
    if (!std::regex_match(target, m, re)) return std::nullopt;
    return trial_page(watch, dirs, m[1].str());
  };
}

/// robozoo-view --experiment DIR: the experiment page, the folder polled.
int run_experiment(Args& a) {
  if (!(a.poll_seconds > 0)) throw std::invalid_argument("--poll must be a positive number of seconds");
  for (const std::string& d : a.watch.results_dirs)
    if (!std::filesystem::is_directory(d)) throw std::invalid_argument("--results " + d + ": not a folder");
  // robozoo-experiment's own results folder (OUT/results) counts by default, and the portable
  // checkpoints of its trials in progress (OUT/checkpoints, as tools/experiment/paper_experiment.sh keeps them).
  for (const char* sub : {"results", "checkpoints"}) {
    const std::string own = (std::filesystem::path(a.experiment) / sub).string();
    if (std::filesystem::is_directory(own) &&
        std::find(a.watch.results_dirs.begin(), a.watch.results_dirs.end(), own) == a.watch.results_dirs.end())
      a.watch.results_dirs.push_back(own);
  }
  fill_dirs(a.dirs);
  const std::function<bool()> should_stop = poll_interrupts();
  ExperimentWatch watch(a.experiment, a.watch);  // throws when there is no experiment
  const AssetTable assets = AssetTable::load(a.dirs);
  ViewState state("experiment", a.experiment, a.state);
  a.server.route = experiment_route(watch, a.dirs);
  Server server(a.server, assets, state);
  server.start();
  size_t from_results = 0;
  for (const TrialProgress& t : watch.trials()) from_results += t.results_path.empty() ? 0 : 1;
  std::cerr << "robozoo-view: open " << address_text(a.server.bind, server.port()) << "experiment.html ("
            << watch.trials().size() << " trials in " << a.experiment;
  if (from_results > 0) std::cerr << ", " << from_results << " of them known from compact results alone";
  std::cerr << ")" << std::endl;
  auto next = std::chrono::steady_clock::now();
  while (!should_stop()) {
    if (std::chrono::steady_clock::now() >= next) {
      watch.poll();
      next = std::chrono::steady_clock::now() + std::chrono::milliseconds(static_cast<int64_t>(a.poll_seconds * 1000));
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  server.stop();
  std::cerr << "robozoo-view: " << watch.trials().size() << " trials, " << server.refused() << " requests refused\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "robozoo-view: watch a robozoo run in the browser, live from the bus or played from a log.\n"
      "  robozoo-view --lcm-url [URL]                 follow a live run (robozoo-evolve --lcm-url)\n"
      "  robozoo-view LOG [--speed S] [--loop | --follow] [--generation G]   play a log\n"
      "  robozoo-view --experiment DIR [--results R]  an experiment's trials as they run (and those of R's\n"
      "                                               compact results, finished elsewhere)\n"
      "  robozoo-view export LOG [--genome N] -o champion.html   one champion as one offline HTML file\n"
      "then open the address it prints (http://127.0.0.1:8080/ by default)."};
  app.set_version_flag("--version", robozoo::version_line());
  Args a;
  app.add_option("LOG", a.log.path, "a log written by robozoo-evolve (or lcm-logger)");
  app.add_option("--lcm-url", a.lcm_url, "follow the run live on this LCM URL (given alone: LCM's default URL)")
      ->expected(0, 1)
      ->default_str(kDefaultLcmUrl);
  app.add_option("--port", a.server.port, "TCP port of the page (0: any free port)")->capture_default_str();
  app.add_option("--bind", a.server.bind, "address to listen on; anything but loopback exposes the run on purpose")
      ->capture_default_str();
  app.add_option("--speed", a.log.speed, "LOG: times real time")->capture_default_str()->check(CLI::PositiveNumber);
  app.add_flag("--loop", a.log.loop, "LOG: play again from the start at the end");
  app.add_flag("--follow", a.log.follow, "LOG: at the end, keep playing what is appended to the log");
  app.add_option("--generation", a.log.generation,
                 "LOG: start playing at this generation (the earlier ones are "
                 "on the chart at once)")
      ->check(CLI::NonNegativeNumber);
  app.add_flag("--exit-at-end", a.log.exit_at_end, "LOG: exit at the end of the log instead of staying up");
  app.add_option("--idle-exit", a.bus.idle_exit,
                 "--lcm-url: exit after this many seconds without a message, once a "
                 "run was seen (0: never)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--stream-timeout", a.bus.stream_timeout,
                 "--lcm-url: a pose stream is over after this many seconds without a message")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  app.add_option("--queue-poses", a.state.queue.max_poses,
                 "poses waiting for a slow page before the oldest are dropped")
      ->capture_default_str();
  app.add_option("--keep-streams", a.state.keep_streams,
                 "--lcm-url: champions whose poses stay in memory for replays (older ones are re-simulated)")
      ->capture_default_str();
  app.add_option("--page-dir", a.dirs.page,
                 "folder of the page's files (default: ../share/robozoo/view beside the "
                 "program)");
  app.add_option("--three-dir", a.dirs.three, "three.js's folder (default: " ROBOZOO_THREE_DIR ")");
  app.add_option("--experiment", a.experiment,
                 "follow an experiment folder (robozoo-experiment --out): every "
                 "trial's fitness, the arms' means and their differences");
  app.add_option("--results", a.watch.results_dirs,
                 "--experiment: also the trials of this folder of compact results (*.results.json) or portable "
                 "checkpoints (*.portable-checkpoint: trials in progress) that DIR has no log of, e.g. run on "
                 "another machine (repeatable; DIR/results and DIR/checkpoints count by default)");
  app.add_option("--poll", a.poll_seconds, "--experiment: look at the folder this often (s)")->capture_default_str();
  app.add_option("--running-seconds", a.watch.running_seconds,
                 "--experiment: a trial whose log or checkpoint changed this recently is running (s)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  app.add_flag("-q,--quiet", a.quiet, "only the address and the final summary");
  CLI::App* exp = app.add_subcommand("export",
                                     "write one champion of a LOG as one self-contained HTML file that "
                                     "plays it offline (no server, no network)");
  exp->add_option("LOG", a.export_options.log, "a log written by robozoo-evolve")->required();
  exp->add_option("--genome", a.export_genome, "the genome to export (default: the log's last champion)");
  exp->add_option("-o,--output", a.export_out, "the HTML file to write")->required();
  exp->add_option("--page-dir", a.dirs.page, "folder of the page's files");
  exp->add_option("--three-dir", a.dirs.three, "three.js's folder");
  app.require_subcommand(0, 1);
  if (const auto stop = robozoo::parse_options(app, argc, argv, "robozoo-view")) return *stop;
  // Bad input or options (std::invalid_argument) exit 2, any other failure 1.
  return exit_status_of("robozoo-view", [&] { return exp->parsed() ? run_export(*exp, a) : run(app, a); });
}
