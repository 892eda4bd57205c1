#include "evolve/app/run_command.hpp"

#include <unistd.h>

#include <filesystem>
#include <iostream>
#include <sstream>
#include <thread>

#include "evolve/config/config_docs.hpp"
#include "evolve/config/run_config.hpp"
#include "evolve/io/bus.hpp"
#include "evolve/record/checkpoint.hpp"
#include "evolve/run/evolution.hpp"
#include "evolve/run/pool_evaluator.hpp"

namespace robozoo {

namespace {
/// The presets: short (population 100, 40 generations) and paper (the defaults).
RunConfig preset_config(const std::string& name) {
  RunConfig c;
  if (name == "short") {
    c.neat.population = 100;
    c.generations = 40;
  } else if (name == "paper") {
    // The paper's settings are the defaults.
  } else {
    throw ConfigError("--preset: unknown preset '" + name + "' (use short or paper)");
  }
  return c;
}
}  // namespace

void add_run_options(CLI::App& app, RunOptions& o) {
  app.add_option("--regime", o.regime, "feedforward (control: CPPNs without cycles) or recurrent (experimental)")
      ->check(CLI::IsMember({"feedforward", "recurrent"}));
  app.add_option("--seed", o.seed, "seed of the run's single random generator");
  app.add_option("--population", o.population, "genomes per generation (paper: 150)")->check(CLI::Range(2, 1000000));
  app.add_option("--generations", o.generations,
                 "generations to run (paper: 500); with --resume, more than the checkpoint's extends the run "
                 "(a finished one too) to what an uninterrupted run of that many generations logs")
      ->check(CLI::Range(1, 1000000000));
  app.add_option("--steps", o.steps, "physics steps of 0.01 s per evaluation (paper: 2500)")
      ->check(CLI::Range(1, 1000000000));
  app.add_option("--workers", o.workers, "worker processes evaluating genomes (default: number of cores)")
      ->check(CLI::Range(1, 4096));
  app.add_option("--config", o.config_file, "configuration file (.json or .toml) with any parameter of the method");
  app.add_option("--set", o.sets,
                 "set one configuration key, after --config: KEY=VALUE with a dotted key and a JSON value or a "
                 "bare name (e.g. neat.initial_links=inputs_to_outputs, sim.target_x=20); repeatable")
      ->take_all();
  app.add_option("--preset", o.preset, "short (population 100, 40 generations) or paper (the paper's sizes)");
  app.add_option("--log", o.log_path, "the run's LCM log (default: runs/<run id>.lcmlog)");
  app.add_option("--lcm-url", o.lcm_url, "publish live on this LCM URL (given alone: LCM's default URL)")
      ->expected(0, 1)
      ->default_str(kDefaultLcmUrl);
  app.add_option("--pose-every", o.pose_every, "publish every k-th step of a new champion's trajectory")
      ->check(CLI::Range(1, 1000000000));
  app.add_option("--bus-rate", o.bus_rate,
                 "live publishing's sustained rate in bytes/s after a 64 kB burst (0: no byte limit); UDP "
                 "multicast drops what a subscriber's receive buffer cannot hold")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app.add_option("--bus-message-rate", o.bus_message_rate,
                 "live publishing's rate in messages/s, one at a time (0: no message limit); LCM drops what "
                 "reaches a subscriber that holds 31 undispatched messages (its default queue: lcm-logger's). "
                 "The log's time stamps follow the same schedule, bus or not, so lcm-logplayer replays a log "
                 "as it was published")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app.add_flag("--publish-all", o.publish_all, "publish every genome and morphology, not only champions");
  app.add_flag("--resume", o.resume, "continue the run of --log from its checkpoint");
  app.add_flag("--force", o.force,
               "with --resume: continue a run whose checkpoint another robozoo version (git commit) wrote");
  app.add_option("--run-id", o.run_id, "identifier of the run (default: <regime>-s<seed>)");
  app.add_option("--job-timeout", o.job_timeout, "seconds before a hung evaluation's worker is replaced")
      ->check(CLI::PositiveNumber);
  app.add_flag("--quiet,-q", o.quiet, "no progress lines");
  app.add_flag("--print-config", o.print_config,
               "print the resolved configuration (JSON, every parameter with its value) and exit");
  app.add_flag("--explain", o.explain,
               "with --print-config: one line per parameter, KEY = VALUE and its meaning and unit, instead of JSON");
  app.add_flag("--mpi", o.mpi,
               "evaluate on the ranks of an MPI job: mpirun -np N robozoo-evolve --mpi ... (N >= 2; rank 0 "
               "evolves, logs and checkpoints, ranks 1..N-1 evaluate; --workers is ignored)");
}

std::optional<int> open_evolution(const RunConfig& config, const EvolveOptions& opts, Evaluator& evaluator,
                                  std::unique_ptr<Evolution>& evo) {
  try {
    evo = std::make_unique<Evolution>(config, opts, evaluator);
  } catch (const std::exception& e) {
    std::cerr << "robozoo-evolve: " << e.what() << "\n";
    return 2;
  }
  if (evo->finished()) {
    std::cerr << "robozoo-evolve: run " << evo->run_id() << " in " << opts.log_path << " is already complete\n";
    return 0;
  }
  // Whether --resume resumed or started afresh is said even with --quiet.
  if (opts.resume) std::cerr << resume_line(*evo, opts) << std::endl;
  return std::nullopt;
}

std::string resume_line(const Evolution& evo, const EvolveOptions& opts) {
  std::ostringstream out;
  out << "robozoo-evolve: ";
  if (evo.resumed())
    out << "resumed run " << evo.run_id() << " at generation " << evo.start_generation() << " of "
        << evo.config().generations << " (" << evo.evaluations() << " evaluations before)";
  else
    out << "no checkpoint " << opts.log_path << ".checkpoint: run " << evo.run_id() << " starts at generation 0";
  return out.str();
}

std::string session_line(const Evolution& evo) {
  return "robozoo-evolve: " + std::to_string(evo.evaluations_this_process()) + " evaluations in this process (" +
         std::to_string(evo.evaluations()) + " in the run), generations " + std::to_string(evo.start_generation()) +
         " to " + std::to_string(evo.config().generations - 1);
}

std::string bus_line(const Evolution& evo) {
  if (evo.publish_failures() < 0) return "";
  return "robozoo-evolve: bus: " + std::to_string(evo.messages_published()) + " messages published, " +
         std::to_string(evo.publish_failures()) + " publish failures";
}

void print_run_end(const Evolution& evo, const EvolveOptions& opts, bool quiet) {
  if (!quiet) std::cerr << "robozoo-evolve: done, log " << opts.log_path << "\n";
  if (!quiet || opts.resume) std::cerr << session_line(evo) << "\n";
  if (!opts.lcm_url.empty()) std::cerr << bus_line(evo) << "\n";
}

std::optional<int> resolve_run(const CLI::App& app, const RunOptions& o, RunConfig& config, EvolveOptions& opts) {
  try {
    config = o.preset.empty() ? RunConfig{} : preset_config(o.preset);
    if (!o.config_file.empty()) config = load_config_file(o.config_file, config);
    for (const auto& kv : o.sets) config = config_from_json(config_assignment(kv), config);
    if (app.count("--regime")) config.regime = regime_from_name(o.regime);
    if (app.count("--seed")) config.seed = o.seed;
    if (app.count("--population")) config.neat.population = o.population;
    if (app.count("--generations")) config.generations = o.generations;
    if (app.count("--steps")) config.eval.sim.steps = o.steps;
    if (app.count("--pose-every")) config.pose_every = o.pose_every;
    if (o.publish_all) config.publish_all = true;
    validate_config(config);
    if (o.explain && !o.print_config) {
      std::cerr << "robozoo-evolve: --explain only applies to --print-config\n";
      return 2;
    }
    if (o.print_config) {
      if (o.explain)
        std::cout << explain_config(config);
      else
        std::cout << config_to_json(config).dump(2) << "\n";
      return 0;
    }
    opts.run_id = o.run_id;
    opts.resume = o.resume;
    opts.force_version = o.force;
    if (o.force && !o.resume) {
      std::cerr << "robozoo-evolve: --force only applies to --resume\n";
      return 2;
    }
    if (app.count("--lcm-url")) opts.lcm_url = o.lcm_url.empty() ? kDefaultLcmUrl : o.lcm_url;
    opts.bus_pacing.bytes_per_second = o.bus_rate;
    opts.bus_pacing.messages_per_second = o.bus_message_rate;
    const std::string id = o.run_id.empty() ? default_run_id(config) : o.run_id;
    opts.log_path = o.log_path.empty() ? "runs/" + id + ".lcmlog" : o.log_path;
    const auto parent = std::filesystem::path(opts.log_path).parent_path();
    if (!parent.empty()) std::filesystem::create_directories(parent);
    const std::string checkpoint = checkpoint_path_for(opts.log_path);
    if (o.resume && std::filesystem::exists(checkpoint)) {
      // A resumed run is the run in the checkpoint: its configuration, not the
      // command line's, decides how the workers evaluate. Evolution resumes from
      // this same reading of it.
      opts.checkpoint = read_checkpoint(checkpoint);
      config = config_from_record(opts.checkpoint->config);
      // --generations on resume moves the run's end: up only (Evolution refuses less).
      if (app.count("--generations")) {
        opts.generations = o.generations;
        if (o.generations < config.generations)
          throw ConfigError("--generations " + std::to_string(o.generations) + ": " + opts.log_path +
                            " was started for " + std::to_string(config.generations) +
                            " generations; a resumed run can be extended, not shortened");
        config.generations = o.generations;
      }
    }
    if (!o.resume && std::filesystem::exists(checkpoint) && std::filesystem::exists(opts.log_path)) {
      // Refuse to silently overwrite a run that could be resumed.
      std::cerr << "robozoo-evolve: " << opts.log_path
                << " already holds a run; use --resume to continue it, or another --log\n";
      return 2;
    }
  } catch (const ConfigError& e) {
    std::cerr << "robozoo-evolve: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "robozoo-evolve: " << e.what() << "\n";
    return 2;
  }
  return std::nullopt;
}

std::string run_banner(const Evolution& evo, const EvolveOptions& opts, const std::string& evaluators) {
  std::ostringstream out;
  out << "robozoo-evolve: run " << evo.run_id() << " (" << regime_name(evo.config().regime) << ", seed "
      << evo.config().seed << ", population " << evo.config().neat.population << ", " << evo.config().generations
      << " generations, " << evaluators << ")"
      << (evo.resumed() ? " resumed at generation " + std::to_string(evo.generation()) : "") << "\n  log "
      << opts.log_path << "\n  checkpoint " << evo.checkpoint_path() << "\n"
      << (opts.lcm_url.empty() ? "" : "  live on " + opts.lcm_url + "\n");
  return out.str();
}

int run_run_command(const CLI::App& app, const RunOptions& o) {
  RunConfig config;
  EvolveOptions opts;
  if (const auto status = resolve_run(app, o, config, opts)) return *status;

  const int workers = o.workers > 0 ? o.workers : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  try {
    // Workers are forked before anything else (no LCM, no open log in them).
    PoolEvaluator evaluator(workers, config.eval, o.job_timeout);
    std::unique_ptr<Evolution> evo;
    if (const auto status = open_evolution(config, opts, evaluator, evo)) return *status;
    if (!o.quiet) std::cerr << run_banner(*evo, opts, std::to_string(workers) + " workers");
    evo->run([&](const ProgressReport& r) {
      if (!o.quiet) std::cerr << format_progress(r) << std::endl;
    });
    print_run_end(*evo, opts, o.quiet);
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "robozoo-evolve: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace robozoo
