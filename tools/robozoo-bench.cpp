// robozoo-bench: how fast one evaluation is, and how close it comes to the
// engine's limit (issue 3). For a fixed, seeded set of random genomes of each
// regime (NEAT mutations from the initial genome, kept when their robot earns
// simulation, so that they grow real robots), it measures on one core:
// evaluations per second; the split of time into CPPN queries, the rest of
// growth, controller + sensors, and ODE stepping; and the ratio of the full
// evaluation time to a bare ODE loop stepping the same bodies and joints for
// the same number of steps with no controller, sensors or bookkeeping,
// measured in the same run.
#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <iostream>

#include <nlohmann/json.hpp>

#include "evolve/config/run_config.hpp"
#include "evolve/cppn/network.hpp"
#include "evolve/fitness/evaluate.hpp"
#include "evolve/growth/growth.hpp"
#include "evolve/neat/random_genome.hpp"
#include "evolve/sim/simulation.hpp"
#include "evolve/core/version.hpp"

using namespace robozoo;
using Clock = std::chrono::steady_clock;

namespace {

double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

struct Totals {
  int genomes = 0, drawn = 0;
  long long queries = 0, steps = 0, spheres = 0;
  double decode = 0, grow = 0, query_estimate = 0, controller = 0, physics = 0, bookkeeping = 0;
  double full = 0, bare = 0;
};

/// Cost of one query of `net`, measured on `n` queries over a circle (the growth pattern).
double seconds_per_query(Network& net, int n) {
  double in[9] = {0, 0, 0, 0.1, 1.0, 0, 0, 0, 0};
  double out[11];
  double sink = 0;
  const auto t0 = Clock::now();
  for (int k = 0; k < n; ++k) {
    in[0] = 0.1 * std::cos(0.01 * k);
    in[1] = 0.1 * std::sin(0.01 * k);
    net.query(in, out);
    sink += out[0];
  }
  const double s = since(t0) / n;
  if (sink == 12345.678) std::puts("");  // keep the loop
  return s;
}

Totals bench_regime(Regime regime, const RunConfig& config, int want, int rounds, uint64_t seed, int max_draws) {
  Totals t;
  Rng rng(seed);
  RandomGenomeParams rp;
  rp.rounds = rounds;
  while (t.genomes < want && t.drawn < max_draws) {
    const Genome g = random_evolved_genome(robot_layout(), regime, config.neat, rp, rng, t.drawn);
    ++t.drawn;
    {
      Network probe(g, robot_layout(), config.eval.cppn_updates);
      if (!grow(probe, config.eval.growth).simulate) continue;
    }
    ++t.genomes;
    // Full evaluation, exactly as a worker does it, untimed inside.
    auto t0 = Clock::now();
    const Evaluation e = evaluate(g, config.eval);
    t.full += since(t0);
    // The same stages, timed one by one.
    t0 = Clock::now();
    Network net(g, robot_layout(), config.eval.cppn_updates);
    t.decode += since(t0);
    t0 = Clock::now();
    const Robot robot = grow(net, config.eval.growth);
    t.grow += since(t0);
    const long long q = net.queries();
    t.queries += q;
    t.query_estimate += q * seconds_per_query(net, 2000);
    t.spheres += static_cast<long long>(robot.spheres.size());
    Simulation sim(robot, config.eval.sim);
    sim.enable_timing(true);
    while (sim.step()) {
    }
    const auto tm = sim.timing();
    t.controller += tm.controller;
    t.physics += tm.physics;
    t.bookkeeping += tm.bookkeeping;
    const int steps = e.sim.steps_run;
    t.steps += steps;
    t0 = Clock::now();
    simulate_bare(robot, config.eval.sim, steps);
    t.bare += since(t0);
    if (t.genomes % 20 == 0) std::cerr << "  " << regime_name(regime) << ": " << t.genomes << "/" << want << "\r" << std::flush;
  }
  std::cerr << "\n";
  return t;
}

nlohmann::json report(const Totals& t) {
  const double staged = t.decode + t.grow + t.controller + t.physics + t.bookkeeping;
  auto share = [&](double x) { return staged > 0 ? x / staged : 0.0; };
  nlohmann::json j;
  j["genomes"] = t.genomes;
  j["genomes_drawn"] = t.drawn;
  j["mean_spheres"] = t.genomes ? double(t.spheres) / t.genomes : 0.0;
  j["mean_steps"] = t.genomes ? double(t.steps) / t.genomes : 0.0;
  j["evaluations_per_second"] = t.full > 0 ? t.genomes / t.full : 0.0;
  j["mean_evaluation_ms"] = t.genomes ? 1e3 * t.full / t.genomes : 0.0;
  j["cppn_queries_per_robot"] = t.genomes ? double(t.queries) / t.genomes : 0.0;
  j["share"] = {{"cppn_decode", share(t.decode)},
                {"cppn_queries", share(t.query_estimate)},
                {"growth_other", share(std::max(0.0, t.grow - t.query_estimate))},
                {"controller_sensors", share(t.controller)},
                {"ode_stepping", share(t.physics)},
                {"bookkeeping", share(t.bookkeeping)}};
  j["bare_ode_seconds"] = t.bare;
  j["full_evaluation_seconds"] = t.full;
  j["ratio_full_to_bare_ode"] = t.bare > 0 ? t.full / t.bare : 0.0;
  return j;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"robozoo-bench: evaluations per second on one core, where the time goes, and the ratio of a full\n"
               "evaluation to a bare ODE loop over the same bodies and joints (the engine's limit)."};
  int genomes = 200, rounds = 30, max_draws = 200000;
  uint64_t seed = 1;
  bool json = false;
  std::string config_file;
  app.add_option("--genomes", genomes, "simulated genomes per regime (default 200)")->check(CLI::Range(1, 100000));
  app.add_option("--mutations", rounds, "mutation rounds of each random genome (default 30)")->check(CLI::Range(0, 10000));
  app.add_option("--seed", seed, "seed of the genome set (default 1)");
  app.add_option("--max-draws", max_draws, "give up after drawing this many genomes per regime");
  app.add_option("--config", config_file, "configuration file (.json or .toml)");
  app.add_flag("--json", json, "print the figures as JSON");
  app.set_version_flag("--version", robozoo::version_line());
  CLI11_PARSE(app, argc, argv);
  RunConfig config;
  try {
    if (!config_file.empty()) config = load_config_file(config_file);
  } catch (const std::exception& e) {
    std::cerr << "robozoo-bench: " << e.what() << "\n";
    return 2;
  }
  nlohmann::json out;
  for (Regime r : {Regime::FeedForward, Regime::Recurrent}) {
    const Totals t = bench_regime(r, config, genomes, rounds, seed, max_draws);
    out[regime_name(r)] = report(t);
  }
  if (json) {
    std::cout << out.dump(2) << "\n";
    return 0;
  }
  for (const auto& [name, j] : out.items()) {
    std::printf("%s: %d simulated genomes (of %d drawn), %.1f spheres, %.0f steps on average\n", name.c_str(),
                j["genomes"].get<int>(), j["genomes_drawn"].get<int>(), j["mean_spheres"].get<double>(),
                j["mean_steps"].get<double>());
    std::printf("  %.1f evaluations/s on one core (%.2f ms each), %.0f CPPN queries per robot\n",
                j["evaluations_per_second"].get<double>(), j["mean_evaluation_ms"].get<double>(),
                j["cppn_queries_per_robot"].get<double>());
    const auto& s = j["share"];
    std::printf("  time: decode %.1f%%, CPPN queries %.1f%%, rest of growth %.1f%%, controller+sensors %.1f%%, "
                "ODE stepping %.1f%%, bookkeeping %.1f%%\n",
                100 * s["cppn_decode"].get<double>(), 100 * s["cppn_queries"].get<double>(),
                100 * s["growth_other"].get<double>(), 100 * s["controller_sensors"].get<double>(),
                100 * s["ode_stepping"].get<double>(), 100 * s["bookkeeping"].get<double>());
    std::printf("  full evaluation / bare ODE loop = %.3f (%.2f s vs %.2f s)\n",
                j["ratio_full_to_bare_ode"].get<double>(), j["full_evaluation_seconds"].get<double>(),
                j["bare_ode_seconds"].get<double>());
  }
  return 0;
}
