// robozoo-view: watch a run in the browser, live from the bus or played from a
// log. One page on http://127.0.0.1:8080, fed over a WebSocket.
#include <signal.h>

#include <CLI/CLI.hpp>

#include <iostream>

#include "evolve/core/version.hpp"
#include "evolve/io/bus.hpp"
#include "view/assets.hpp"
#include "view/bus_feed.hpp"
#include "view/log_feed.hpp"
#include "view/server.hpp"
#include "view/view_state.hpp"
#include "util/stop_signals.hpp"

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
};

std::string address_text(const std::string& bind, unsigned short port) {
  const std::string host = bind.find(':') != std::string::npos ? "[" + bind + "]" : bind == "0.0.0.0" ? "127.0.0.1" : bind;
  return "http://" + host + ":" + std::to_string(port) + "/";
}

int run(CLI::App& app, Args& a) {
  const bool live = app.count("--lcm-url") > 0;
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
  const AssetDirs defaults = default_asset_dirs();
  if (a.dirs.page.empty()) a.dirs.page = defaults.page;
  if (a.dirs.three.empty()) a.dirs.three = defaults.three;

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

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "robozoo-view: watch a robozoo run in the browser, live from the bus or played from a log.\n"
      "  robozoo-view --lcm-url [URL]                 follow a live run (robozoo-evolve --lcm-url)\n"
      "  robozoo-view LOG [--speed S] [--loop | --follow] [--generation G]   play a log\n"
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
  app.add_option("--generation", a.log.generation, "LOG: start playing at this generation (the earlier ones are "
                                                   "on the chart at once)")
      ->check(CLI::NonNegativeNumber);
  app.add_flag("--exit-at-end", a.log.exit_at_end, "LOG: exit at the end of the log instead of staying up");
  app.add_option("--idle-exit", a.bus.idle_exit, "--lcm-url: exit after this many seconds without a message, once a "
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
  app.add_option("--page-dir", a.dirs.page, "folder of the page's files (default: ../share/robozoo/view beside the "
                                            "program)");
  app.add_option("--three-dir", a.dirs.three, "three.js's folder (default: " ROBOZOO_THREE_DIR ")");
  app.add_flag("-q,--quiet", a.quiet, "only the address and the final summary");
  CLI11_PARSE(app, argc, argv);
  try {
    return run(app, a);
  } catch (const std::exception& e) {
    std::cerr << "robozoo-view: " << e.what() << "\n";
    return 1;
  }
}
