// robozoo-bench: how fast one evaluation is, and how close it comes to the
// engine's limit. For a fixed, seeded set of random genomes of each regime (NEAT
// mutations from the initial genome, kept when their robot earns simulation, so
// that they grow real robots), and with --log for the population of a logged
// run's last generation (robots as evolution makes them), it measures on one
// core: evaluations per second; the split of time into CPPN decoding, CPPN
// queries, the rest of growth, controller + sensors, ODE stepping and
// bookkeeping; and the ratio of the full evaluation time to a bare ODE loop
// stepping the same bodies and joints for the same number of steps with no
// controller, sensors or bookkeeping, measured in the same run. Every genome is
// measured twice, alternating: with robozoo's own activation functions (what
// every program uses) and with the C library's exp/cos/sin (the baseline, "before";
// the CTRNN's tanh is robozoo's in both).
#include <CLI/CLI.hpp>

#include <ctime>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "evolve/config/run_config.hpp"
#include "evolve/core/cpu_time.hpp"
#include "evolve/cppn/network.hpp"
#include "evolve/fitness/evaluate.hpp"
#include "evolve/growth/growth.hpp"
#include "evolve/neat/start/random_genome.hpp"
#include "evolve/record/checkpoint.hpp"
#include "evolve/sim/episode/simulation.hpp"
#include "evolve/core/version.hpp"
#include "util/parse_options.hpp"

using namespace robozoo;
namespace {

/// This thread's CPU time: the machine may be shared, and wall time would count
/// the time other processes hold the core.
struct Clock {
  using time_point = double;
  static double now() { return thread_cpu_seconds(); }
};

double since(double t0) { return Clock::now() - t0; }

struct Totals {
  int genomes = 0, drawn = 0, simulated = 0;
  long long queries = 0, weight_queries = 0, steps = 0, spheres = 0, contacts = 0, bare_contacts = 0;
  double decode = 0, grow = 0, query = 0, controller = 0, physics = 0, bookkeeping = 0;
  double full = 0, bare = 0;
};

/// Evaluates g as a worker does (evaluate(): decode, grow, simulate; with
/// libm_activations, the same steps with the C library's activations), timed as
/// a whole, then again stage by stage, then steps the same robot in the bare ODE
/// loop.
void measure(const Genome& g, const EvalParams& eval, bool libm_activations, Totals& t) {
  ++t.genomes;
  auto t0 = Clock::now();
  int steps = 0;
  if (!libm_activations) {
    steps = evaluate(g, eval).sim.steps_run;
  } else {
    Network cppn(g, robot_layout(), eval.cppn_updates);
    cppn.use_libm_activations(true);
    const Robot grown = grow(cppn, eval.growth);
    if (grown.simulate) steps = simulate(grown, eval.sim).steps_run;
  }
  t.full += since(t0);
  t0 = Clock::now();
  Network net(g, robot_layout(), eval.cppn_updates);
  t.decode += since(t0);
  net.use_libm_activations(libm_activations);
  net.enable_timing(true);
  t0 = Clock::now();
  const Robot robot = grow(net, eval.growth);
  t.grow += since(t0);
  t.query += net.query_seconds();
  t.queries += net.queries();
  t.spheres += static_cast<long long>(robot.spheres.size());
  const auto ns = static_cast<long long>(robot.sensors.size()), nn = static_cast<long long>(robot.neurons.size());
  t.weight_queries += ns * nn + nn * (nn + 1) / 2;  // set_ctrnn_weights: sensor x neuron, neuron pairs
  if (!robot.simulate) return;
  ++t.simulated;
  Simulation sim(robot, eval.sim);
  sim.enable_timing(true);
  while (sim.step()) {
  }
  const auto tm = sim.timing();
  t.controller += tm.controller;
  t.physics += tm.physics;
  t.bookkeeping += tm.bookkeeping;
  t.contacts += tm.contacts;
  t.steps += steps;
  t0 = Clock::now();
  t.bare_contacts += simulate_bare(robot, eval.sim, steps);
  t.bare += since(t0);
}

struct BeforeAfter {
  Totals libm, own;  // the C library's activations (before), robozoo's (after)
};

void measure_both(const Genome& g, const EvalParams& eval, bool baseline, BeforeAfter& t) {
  if (baseline) measure(g, eval, true, t.libm);
  measure(g, eval, false, t.own);
}

BeforeAfter bench_random(Regime regime, const RunConfig& config, int want, const RandomGenomeParams& rp, uint64_t seed,
                         int max_draws, bool baseline) {
  BeforeAfter ba;
  Totals& t = ba.own;
  Rng rng(seed);
  int drawn = 0;
  while (t.genomes < want && drawn < max_draws) {
    const Genome g = random_evolved_genome(robot_layout(), regime, config.neat, rp, rng, drawn);
    ++drawn;
    {
      Network probe(g, robot_layout(), config.eval.cppn_updates);
      if (!grow(probe, config.eval.growth).simulate) continue;
    }
    measure_both(g, config.eval, baseline, ba);
    if (t.genomes % 20 == 0)
      std::cerr << "  " << regime_name(regime) << ": " << t.genomes << "/" << want << "\r" << std::flush;
  }
  t.drawn = ba.libm.drawn = drawn;
  std::cerr << "\n";
  return ba;
}

BeforeAfter bench_population(const std::vector<Genome>& genomes, const RunConfig& config, bool baseline) {
  BeforeAfter ba;
  Totals& t = ba.own;
  for (const Genome& g : genomes) {
    measure_both(g, config.eval, baseline, ba);
    if (t.genomes % 10 == 0)
      std::cerr << "  log population: " << t.genomes << "/" << genomes.size() << "\r" << std::flush;
  }
  t.drawn = ba.libm.drawn = t.genomes;
  std::cerr << "\n";
  return ba;
}

nlohmann::json report(const Totals& t) {
  const double staged = t.decode + t.grow + t.controller + t.physics + t.bookkeeping;
  auto share = [&](double x) { return staged > 0 ? x / staged : 0.0; };
  auto per = [](double x, int n) { return n ? x / n : 0.0; };
  nlohmann::json j;
  j["genomes"] = t.genomes;
  j["genomes_drawn"] = t.drawn;
  j["simulated"] = t.simulated;
  j["mean_spheres"] = per(double(t.spheres), t.genomes);
  j["mean_steps"] = per(double(t.steps), t.simulated);
  j["evaluations_per_second"] = t.full > 0 ? t.genomes / t.full : 0.0;
  j["mean_evaluation_ms"] = 1e3 * per(t.full, t.genomes);
  j["cppn_queries_per_robot"] = per(double(t.queries), t.genomes);
  j["cppn_weight_queries_per_robot"] = per(double(t.weight_queries), t.genomes);
  j["cppn_query_us"] = t.queries ? 1e6 * t.query / double(t.queries) : 0.0;
  j["share"] = {{"cppn_decode", share(t.decode)},
                {"cppn_queries", share(t.query)},
                {"growth_other", share(std::max(0.0, t.grow - t.query))},
                {"controller_sensors", share(t.controller)},
                {"ode_stepping", share(t.physics)},
                {"bookkeeping", share(t.bookkeeping)}};
  j["stage_seconds"] = {{"cppn_decode", t.decode},
                        {"cppn_queries", t.query},
                        {"growth_other", std::max(0.0, t.grow - t.query)},
                        {"controller_sensors", t.controller},
                        {"ode_stepping", t.physics},
                        {"bookkeeping", t.bookkeeping}};
  // The bare loop holds the motors still, so its robots settle where evaluated
  // ones move: the contacts per step say whether the solver had the same work.
  j["contacts_per_step"] = t.steps ? double(t.contacts) / double(t.steps) : 0.0;
  j["bare_contacts_per_step"] = t.steps ? double(t.bare_contacts) / double(t.steps) : 0.0;
  j["bare_ode_seconds"] = t.bare;
  j["full_evaluation_seconds"] = t.full;
  j["ratio_full_to_bare_ode"] = t.bare > 0 ? t.full / t.bare : 0.0;
  return j;
}

void print_one(const std::string& name, const nlohmann::json& j) {
  std::printf("%s: %d genomes (%d simulated, of %d drawn), %.1f spheres, %.0f steps on average\n", name.c_str(),
              j["genomes"].get<int>(), j["simulated"].get<int>(), j["genomes_drawn"].get<int>(),
              j["mean_spheres"].get<double>(), j["mean_steps"].get<double>());
  std::printf(
      "  %.1f evaluations/s on one core (%.2f ms each), %.0f CPPN queries per robot (%.0f of them for weights; "
      "%.3f us each)\n",
      j["evaluations_per_second"].get<double>(), j["mean_evaluation_ms"].get<double>(),
      j["cppn_queries_per_robot"].get<double>(), j["cppn_weight_queries_per_robot"].get<double>(),
      j["cppn_query_us"].get<double>());
  const auto& s = j["share"];
  std::printf(
      "  time: decode %.1f%%, CPPN queries %.1f%%, rest of growth %.1f%%, controller+sensors %.1f%%, "
      "ODE stepping %.1f%%, bookkeeping %.1f%%\n",
      100 * s["cppn_decode"].get<double>(), 100 * s["cppn_queries"].get<double>(),
      100 * s["growth_other"].get<double>(), 100 * s["controller_sensors"].get<double>(),
      100 * s["ode_stepping"].get<double>(), 100 * s["bookkeeping"].get<double>());
  std::printf("  full evaluation / bare ODE loop = %.3f (%.2f s vs %.2f s; ODE stepping in the evaluation %.2f s)\n",
              j["ratio_full_to_bare_ode"].get<double>(), j["full_evaluation_seconds"].get<double>(),
              j["bare_ode_seconds"].get<double>(), j["stage_seconds"]["ode_stepping"].get<double>());
  std::printf("  contacts per step: %.1f evaluated, %.1f in the bare loop (motors held still)\n",
              j["contacts_per_step"].get<double>(), j["bare_contacts_per_step"].get<double>());
}

void print(const std::string& name, const nlohmann::json& j) {
  print_one(name + " (robozoo's activations)", j);
  if (j.contains("libm_activations")) print_one(name + " (C library's activations, before)", j["libm_activations"]);
}

/// The figures of `ba`: robozoo's activations, and under "libm_activations" the baseline's.
nlohmann::json report_both(const BeforeAfter& ba, bool baseline) {
  nlohmann::json j = report(ba.own);
  if (baseline) j["libm_activations"] = report(ba.libm);
  return j;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "robozoo-bench: evaluations per second on one core, where the time goes, and the ratio of a full\n"
      "evaluation to a bare ODE loop over the same bodies and joints (the engine's limit)."};
  int genomes = 200, rounds = 30, max_draws = 200000;
  uint64_t seed = 1;
  bool json = false, log_only = false, no_baseline = false;
  std::string config_file, log_path, regime_opt = "both";
  app.add_option("--genomes", genomes, "simulated random genomes per regime (default 200)")
      ->check(CLI::Range(1, 100000));
  app.add_option("--mutations", rounds, "mutation rounds of each random genome (default 30)")
      ->check(CLI::Range(0, 10000));
  app.add_option("--seed", seed, "seed of the genome set (default 1)");
  app.add_option("--max-draws", max_draws, "give up after drawing this many genomes per regime");
  app.add_option("--log", log_path,
                 "also measure the population of this logged run's last generation (read from LOG.checkpoint:\n"
                 "the last generation of a finished run, the next one bred of an unfinished run)");
  app.add_option("--regime", regime_opt, "random genomes of: feedforward, recurrent or both (default both)")
      ->check(CLI::IsMember({"feedforward", "recurrent", "both"}));
  app.add_flag("--log-only", log_only, "with --log: measure the logged population only, no random genomes");
  app.add_option("--config", config_file, "configuration file (.json or .toml) for the random genomes");
  app.add_flag("--no-baseline", no_baseline,
               "measure robozoo's activations only, not also the C library's (the baseline, half the time)");
  app.add_flag("--json", json, "print the figures as JSON (per regime; the baseline's under \"libm_activations\")");
  app.set_version_flag("--version", robozoo::version_line());
  if (const auto stop = robozoo::parse_options(app, argc, argv, "robozoo-bench")) return *stop;
  if (log_only && log_path.empty()) {
    std::cerr << "robozoo-bench: --log-only needs --log LOG\n";
    return 2;
  }
  RunConfig config;
  Checkpoint checkpoint;
  RunConfig log_config;
  try {
    if (!config_file.empty()) config = load_config_file(config_file);
    if (!log_path.empty()) {
      if (!std::filesystem::is_regular_file(log_path)) throw std::runtime_error("no log file " + log_path);
      checkpoint = read_checkpoint(checkpoint_path_for(log_path));
      log_config = config_from_record(checkpoint.config);
      if (checkpoint.population.genomes.empty()) throw std::runtime_error(log_path + ".checkpoint holds no genomes");
    }
  } catch (const std::exception& e) {
    std::cerr << "robozoo-bench: " << e.what() << "\n";
    return 2;
  }
  nlohmann::json out;
  std::vector<std::string> names;
  if (!log_only) {
    for (Regime r : {Regime::FeedForward, Regime::Recurrent}) {
      if (regime_opt != "both" && regime_opt != regime_name(r)) continue;
      RandomGenomeParams rp;
      rp.rounds = rounds;
      const BeforeAfter t = bench_random(r, config, genomes, rp, seed, max_draws, !no_baseline);
      std::string name = regime_name(r);
      nlohmann::json j = report_both(t, !no_baseline);
      j["initial_links"] = initial_links_name(config.neat.initial_links);
      out[name] = j;
      names.push_back(name);
    }
  }
  if (!log_path.empty()) {
    const BeforeAfter t = bench_population(checkpoint.population.genomes, log_config, !no_baseline);
    nlohmann::json j = report_both(t, !no_baseline);
    j["log"] = log_path;
    j["regime"] = regime_name(log_config.regime);
    j["generation"] = checkpoint.population.generation;
    j["run_finished"] = checkpoint.finished;
    out["log_population"] = j;
    names.push_back("log_population");
  }
  if (json) {
    std::cout << out.dump(2) << "\n";
    return 0;
  }
  for (const std::string& name : names) print(name, out[name]);
  return 0;
}
