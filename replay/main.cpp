// robozoo-replay: check that logged runs are deterministic, replay them on an
// LCM bus, and re-simulate a logged genome live.
#include <unistd.h>

#include <CLI/CLI.hpp>

#include <chrono>
#include <iostream>
#include <memory>
#include <sstream>
#include <thread>

#include "evolve/io/bus.hpp"
#include "evolve/parallel/mpi/mpi_session.hpp"
#include "evolve/parallel/mpi/mpi_transport.hpp"
#include "evolve/parallel/mpi/mpi_worker.hpp"
#include "evolve/run/eval_job.hpp"
#include "evolve/run/pool_evaluator.hpp"
#include "replay/check/check.hpp"
#include "replay/check/full_check.hpp"
#include "replay/check/live_check.hpp"
#include "evolve/config/run_config.hpp"
#include "util/stop_signals.hpp"
#include "replay/sim/live_sim.hpp"
#include "runlog/play/player.hpp"
#include "evolve/core/version.hpp"
#include "runlog/progress_bar.hpp"
#include "util/exit_status.hpp"
#include "util/parse_options.hpp"

namespace {

using namespace robozoo;
using namespace robozoo::replay;

struct CheckArgs {
  std::string log;
  CheckOptions options;  ///< --tolerance, --force, --all-genomes, --max-mismatches (shared by --lcm-url and --full)
  bool json = false, quiet = false, progress = false, no_progress = false;
  bool full = false;              ///< re-run the whole evolution and compare every message
  FullCheckOptions full_options;  ///< --generations
  int workers = 0;                ///< --full: worker processes (0: one per core)
  std::string lcm_url;            ///< check --lcm-url: follow a live run instead of a log
  LiveCheckOptions live_options;  ///< --set
  double idle_exit = 0.0;
};

/// --lcm-url: follow a run on the bus and check its champions as they come.
int run_live_check(const CheckArgs& a) {
  LiveCheckOptions o = a.live_options;
  o.tolerance = a.options.tolerance;
  o.force = a.options.force;
  o.keep = a.options.keep;
  try {
    for (const auto& kv : o.sets) config_assignment(kv);  // a bad assignment is said before the bus starts
  } catch (const std::exception& e) {
    std::cerr << "robozoo-replay: --set: " << e.what() << "\n";
    return 2;
  }
  const std::function<bool()> should_stop = poll_interrupts();
  std::ostringstream sink;
  std::ostream& out = a.quiet ? static_cast<std::ostream&>(sink) : std::cout;
  std::ostream& log = a.quiet ? static_cast<std::ostream&>(sink) : std::cerr;
  try {
    const LiveCheckSummary s = check_live(a.lcm_url, o, a.idle_exit, should_stop, out, log);
    out << format_live_summary(s);
    return s.exit_code();
  } catch (const std::exception& e) {
    std::cerr << "robozoo-replay: " << e.what() << "\n";
    return 2;
  }
}

/// --full: the re-run, on local workers or (session) on the ranks of an MPI job.

/// A bar on the terminal unless --quiet or --no-progress; --progress asks for it anywhere.
bool progress_bar_wanted(const CheckArgs& a) {
  return !a.quiet && !a.no_progress && (a.progress || ::isatty(STDERR_FILENO));
}

/// Prints a check's report (JSON with --json, else `text` unless --quiet); returns its exit code.
template <class Report>
int print_report(const CheckArgs& a, const Report& report, const std::string& text) {
  if (a.json)
    std::cout << to_json(report).dump(2) << "\n";
  else if (!a.quiet)
    std::cout << text;
  return report.exit_code();
}

int run_full_check(const CheckArgs& a, const MpiSession* session) {
  FullCheckOptions o = a.full_options;
  o.force = a.options.force;
  const bool bar_on = progress_bar_wanted(a);
  ProgressBar bar(std::cerr, "re-running");
  FullCheckProgress progress = [&](int done, int total, double elapsed) {
    if (bar_on)
      bar.update(done, total, elapsed);
    else if (!a.quiet)
      std::cerr << "robozoo-replay: check --full: " << progress_text("generation", done, total, elapsed, 20) << "\n";
  };
  const int workers = a.workers > 0 ? a.workers : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  // Under MPI the transport exists before anything can fail: whichever way rank 0
  // leaves, it releases the worker ranks.
  std::unique_ptr<PoolEvaluator> evaluator;
  MpiTransport* transport = nullptr;
  if (session) {
    auto owned = std::make_unique<MpiTransport>();
    transport = owned.get();
    evaluator = std::make_unique<PoolEvaluator>(std::move(owned));
  }
  EvaluatorFactory make = [&](const RunConfig& config) -> Evaluator& {
    if (transport)
      transport->start(config_to_json(config).dump());
    else
      evaluator = std::make_unique<PoolEvaluator>(workers, config.eval);
    return *evaluator;
  };
  if (!a.quiet)
    std::cerr << "robozoo-replay: check --full " << a.log << ": re-running its evolution on "
              << (session ? std::to_string(session->size() - 1) + " MPI worker ranks"
                          : std::to_string(workers) + " workers")
              << " (this costs one evolution)\n";
  const FullCheckReport report = full_check(a.log, make, o, progress);
  bar.finish();
  return print_report(a, report, format_full_text(report));
}

struct PlayArgs {
  std::string log;
  std::string lcm_url = kDefaultLcmUrl;
  PlayOptions options;
  bool quiet = false;
};

struct SimArgs {
  std::string log;
  std::string lcm_url = kDefaultLcmUrl;
  LiveSimOptions options;
  bool quiet = false;
};

int run_check(const CheckArgs& a) {
  const CheckOptions& o = a.options;
  const bool bar_on = progress_bar_wanted(a);
  ProgressBar bar(std::cerr, "checking");
  const auto t0 = std::chrono::steady_clock::now();
  CheckProgress progress;
  if (bar_on)
    progress = [&](size_t done, size_t total) {
      bar.update(static_cast<int64_t>(done), static_cast<int64_t>(total),
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    };
  const CheckReport report = check_log_file(a.log, o, progress);
  bar.finish();
  return print_report(a, report, format_text(report));
}

/// Reads a log for play or sim; prints its damage as warnings.
bool load(const std::string& path, bool quiet, ScannedLog& scanned, LogIndex& index) {
  try {
    scanned = scan_event_log(path);
  } catch (const std::exception& e) {
    std::cerr << "robozoo-replay: " << e.what() << "\n";
    return false;
  }
  index = index_log(scanned.contents);
  if (!quiet) {
    for (const auto& d : scanned.damage)
      std::cerr << "robozoo-replay: warning: " << path << ": " << d.describe() << "\n";
    for (const auto& p : index.problems)
      std::cerr << "robozoo-replay: warning: event " << p.eventnum << " (" << p.channel << "): " << p.what << "\n";
  }
  return true;
}

int run_play(const PlayArgs& a) {
  ScannedLog scanned;
  LogIndex index;
  if (!load(a.log, a.quiet, scanned, index)) return 2;
  const PlayOptions& o = a.options;
  return exit_status_of("robozoo-replay", [&] {
    plan_pass(scanned.contents, index, o);  // bad options are reported before the bus starts
    Bus bus(a.lcm_url);
    SteadyPlayClock clock;
    if (!a.quiet)
      std::cerr << "robozoo-replay: playing " << a.log << " on " << a.lcm_url << " at " << o.speed << "x"
                << (o.loop ? ", looping" : "") << "\n";
    const PlayStats s = play(scanned.contents, index, o, clock,
                             [&](const std::string& ch, const std::vector<uint8_t>& d) { return bus.publish(ch, d); });
    if (!a.quiet)
      std::cerr << "robozoo-replay: sent " << s.events_sent << " events (" << s.state_events_sent
                << " of them state first) in " << s.passes << " pass" << (s.passes == 1 ? "" : "es") << "\n";
    if (s.publish_failures) {
      std::cerr << "robozoo-replay: " << s.publish_failures << " events could not be sent\n";
      return 1;
    }
    return 0;
  });
}

int run_sim(const SimArgs& a) {
  ScannedLog scanned;
  LogIndex index;
  if (!load(a.log, a.quiet, scanned, index)) return 2;
  return exit_status_of("robozoo-replay", [&] {
    Bus bus(a.lcm_url);
    SteadyPlayClock clock;
    const LiveSimStats s =
        live_simulate(scanned.contents, index, a.options, clock,
                      [&](const std::string& ch, const std::vector<uint8_t>& d) { return bus.publish(ch, d); });
    if (!a.quiet)
      std::cerr << "robozoo-replay: re-simulated genome " << a.options.genome_id << " (run " << s.run_id
                << ", generation " << s.generation << ")"
                << (s.simulated_in_evolution ? "" : " (not simulated in evolution: its r term is under 15)") << ": "
                << s.steps_run << " steps, d = " << s.d << " m, " << s.poses_sent << " poses sent on " << a.lcm_url
                << "\n";
    return s.publish_failures ? 1 : 0;
  });
}

}  // namespace

int main(int argc, char** argv) {
  std::unique_ptr<MpiSession> session;
  if (robozoo::mpi_requested(argc, argv)) {
    try {
      session = std::make_unique<MpiSession>(&argc, &argv);
    } catch (const std::exception& e) {
      std::cerr << "robozoo-replay: --mpi: " << e.what() << "\n";
      return 2;
    }
    if (session->rank() != 0) {
      // A worker rank: evaluate rank 0's jobs with the logged run's configuration.
      try {
        serve_mpi_session([](const std::string& setup) { return WorkFn(eval_work_from_setup(setup)); });
        return 0;
      } catch (const std::exception& e) {
        std::cerr << "robozoo-replay: rank " << session->rank() << " on " << session->host() << ": " << e.what()
                  << "\n";
        session->abort(1);
      }
    }
  }
  CLI::App app{
      "robozoo-replay: re-grow and re-simulate the genomes of a robozoo log (written by robozoo-evolve or\n"
      "recorded by lcm-logger) with the same code and the configuration of the log's ROBOZOO_RUN."};
  app.set_version_flag("--version", robozoo::version_line());
  app.require_subcommand(1);

  CheckArgs c;
  CLI::App* check = app.add_subcommand(
      "check",
      "Check every champion: grow it and compare the morphology field by field, re-simulate it and prove its "
      "pose stream (every step once, in order, bit for bit), re-evaluate it and compare the fitness; prove every "
      "message in its place (one run_t first, one generation_t per generation with figures that agree). With "
      "--full, re-run the whole evolution from the log's seed and configuration instead and compare every "
      "message (utime and timings left out): that costs one evolution (--workers N, or mpirun -np N "
      "robozoo-replay check --full --mpi LOG). Exit 0: everything matches; 1: a divergence; 2: unusable input.");
  check->add_option("LOG", c.log, "the LCM log (not with --lcm-url)");
  check
      ->add_option("--lcm-url", c.lcm_url,
                   "follow a live run on the bus instead (given alone: LCM's default URL) and check each champion "
                   "as its generation completes; bus loss is reported apart from divergence")
      ->expected(0, 1)
      ->default_str(kDefaultLcmUrl);
  check
      ->add_option("--idle-exit", c.idle_exit,
                   "--lcm-url: finish after this many seconds without a message (0: "
                   "at a signal only)")
      ->check(CLI::NonNegativeNumber);
  check
      ->add_option("--set", c.live_options.sets,
                   "--lcm-url: change a key of the run's configuration before re-computing (KEY=VALUE, as "
                   "robozoo-evolve --set): what would differ under another setting")
      ->take_all();
  check
      ->add_option("--tolerance", c.options.tolerance,
                   "allowed error |a-b|/max(1,|a|,|b|) for logs made on another machine (default 0: bit for bit)")
      ->check(CLI::NonNegativeNumber);
  check->add_flag("--json", c.json, "print the report as JSON");
  check->add_flag("--force", c.options.force, "check runs written by another robozoo version");
  check->add_flag("--all-genomes", c.options.all_genomes,
                  "check every logged genome (--publish-all runs), not only champions");
  check->add_option("--max-mismatches", c.options.keep, "differences listed per genome in the JSON report")
      ->check(CLI::Range(1, 1000000));
  check->add_flag("--progress", c.progress, "show the progress bar even when stderr is not a terminal");
  check->add_flag("--no-progress", c.no_progress, "no progress bar");
  check->add_flag("--quiet,-q", c.quiet, "no output; the exit status only");
  check->add_flag("--full", c.full,
                  "re-run the whole evolution (seed and configuration of the log's ROBOZOO_RUN) and compare every "
                  "message with the log; costs as much time as the run took to evolve");
  check->add_option("--workers", c.workers, "--full: worker processes (default: one per core)")
      ->check(CLI::Range(1, 4096));
  check->add_option("--generations", c.full_options.max_generations, "--full: re-run at most this many generations")
      ->check(CLI::Range(1, 1000000000));
  bool mpi_flag = false;
  check->add_flag("--mpi", mpi_flag, "--full: evaluate on the ranks of an MPI job (mpirun -np N, N >= 2)");

  PlayArgs p;
  CLI::App* playc = app.add_subcommand(
      "play",
      "Republish the log on an LCM bus at real-time speed. The latest ROBOZOO_RUN and the current champion's "
      "genome and morphology always go out before its poses, so a viewer that joins can draw at once.");
  playc->add_option("LOG", p.log, "the LCM log")->required();
  playc->add_option("--lcm-url", p.lcm_url, "LCM URL to publish on (given alone: LCM's default URL)")
      ->expected(0, 1)
      ->capture_default_str();
  playc->add_option("--speed", p.options.speed, "times real time")->check(CLI::PositiveNumber)->capture_default_str();
  playc->add_option("--channels", p.options.channels, "regular expression of the channels to play (whole name)")
      ->capture_default_str();
  playc->add_flag("--loop", p.options.loop, "start again after the last event, until interrupted");
  playc->add_option("--start-generation", p.options.start_generation, "skip the events of earlier generations")
      ->check(CLI::NonNegativeNumber);
  playc->add_flag_callback(
      "--log-time", [&p] { p.options.pace_poses_by_sim_time = false; },
      "pace poses by their log timestamps (a trajectory is logged in one burst) instead of their "
      "simulated time");
  playc->add_flag("--quiet,-q", p.quiet, "no messages");

  SimArgs s;
  CLI::App* simc = app.add_subcommand(
      "sim",
      "Re-simulate one logged genome and publish its full-rate pose stream at real time (after its run, genome "
      "and morphology), e.g. for robozoo-render live.");
  simc->add_option("LOG", s.log, "the LCM log")->required();
  simc->add_option("--genome", s.options.genome_id, "genome id")->required();
  simc->add_option("--run-id", s.options.run_id, "its run (only needed when the log holds several runs)");
  simc->add_option("--lcm-url", s.lcm_url, "LCM URL to publish on (given alone: LCM's default URL)")
      ->expected(0, 1)
      ->capture_default_str();
  simc->add_option("--speed", s.options.speed, "times real time")->check(CLI::PositiveNumber)->capture_default_str();
  simc->add_option("--pose-every", s.options.pose_every, "publish every k-th step")
      ->check(CLI::Range(1, 1000000000))
      ->capture_default_str();
  simc->add_flag("--force", s.options.force, "accept a run written by another robozoo version");
  simc->add_flag("--quiet,-q", s.quiet, "no messages");

  if (const auto stop = robozoo::parse_options(app, argc, argv, "robozoo-replay")) return *stop;
  if (check->parsed() && check->count("--lcm-url")) {
    if (c.lcm_url.empty()) c.lcm_url = kDefaultLcmUrl;
    if (!c.log.empty() || c.full || c.options.all_genomes) {
      std::cerr << "robozoo-replay: check --lcm-url follows the bus: no LOG, --full or --all-genomes\n";
      return 2;
    }
    if (session) {
      std::cerr << "robozoo-replay: --mpi is for check --full\n";
      return 2;
    }
    return run_live_check(c);
  }
  if (check->parsed() && c.log.empty()) {
    std::cerr << "robozoo-replay: check needs a LOG (or --lcm-url)\n";
    return 2;
  }
  if (check->parsed() && (c.idle_exit > 0 || !c.live_options.sets.empty())) {
    std::cerr << "robozoo-replay: --idle-exit and --set are for check --lcm-url\n";
    return 2;
  }
  if (session && !(check->parsed() && c.full)) {
    std::cerr << "robozoo-replay: --mpi is for check --full\n";
    return 2;
  }
  if (check->parsed() && c.full) {
    if (session && session->size() < 2) {
      std::cerr << "robozoo-replay: --mpi needs at least 2 ranks (rank 0 compares, ranks 1.. evaluate)\n";
      return 2;
    }
    if (c.options.tolerance > 0 || c.options.all_genomes) {
      std::cerr << "robozoo-replay: --full compares every message bit for bit; --tolerance and --all-genomes do not "
                   "apply\n";
      return 2;
    }
    return run_full_check(c, session.get());
  }
  if (check->parsed()) return run_check(c);
  if (playc->parsed()) return run_play(p);
  return run_sim(s);
}
