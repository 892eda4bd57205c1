// robozoo-simstats: simulates random robots (evolve/sim/robots/random_robot) and
// reports how the physics and the fitness rules treat them: the share of each
// outcome, acceleration and spin statistics, and simulation speed. Used to tune
// SimParams' defaults (see evolve/sim/README.md); --csv writes one row per robot.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <vector>

#include <CLI/CLI.hpp>

#include "evolve/core/rng.hpp"
#include "evolve/sim/robots/random_robot.hpp"
#include "evolve/sim/episode/simulation.hpp"
#include "evolve/core/version.hpp"
#include "util/parse_options.hpp"

using namespace robozoo;

namespace {

double median(std::vector<double> v) {
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}
double quantile(std::vector<double> v, double q) {
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<size_t>(q * v.size()))];
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Simulate random robots and report outcome shares, accelerations, spin and speed."};
  int robots = 200;
  uint64_t seed = 1;
  std::string csv;
  RandomRobotParams rp;
  SimParams sp;
  bool bench = false;
  std::vector<int> bench_sizes{1, 10, 30, 50};
  int bench_robots = 10;
  app.add_option("--robots", robots, "number of random robots")->check(CLI::PositiveNumber);
  app.add_option("--seed", seed, "seed of the robot generator");
  app.add_option("--min-spheres", rp.min_spheres, "fewest spheres per robot");
  app.add_option("--max-spheres", rp.max_spheres, "most spheres per robot");
  app.add_option("--joint-probability", rp.joint_probability, "probability that a new sphere is jointed");
  app.add_option("--csv", csv, "write one row per robot to this file");
  app.add_option("--steps", sp.steps, "physics steps per robot");
  app.add_option("--motor-strength", sp.motor_strength, "SimParams.motor_strength");
  app.add_option("--servo-gain", sp.servo_gain, "SimParams.servo_gain");
  app.add_option("--servo-max-speed", sp.servo_max_speed, "SimParams.servo_max_speed");
  app.add_option("--erp", sp.erp, "SimParams.erp");
  app.add_option("--cfm", sp.cfm, "SimParams.cfm");
  app.add_option("--contact-erp", sp.contact_erp, "SimParams.contact_erp");
  app.add_option("--contact-cfm", sp.contact_cfm, "SimParams.contact_cfm");
  app.add_option("--friction", sp.friction, "SimParams.friction");
  app.add_option("--max-correcting-velocity", sp.max_correcting_velocity, "SimParams.max_correcting_velocity");
  app.add_option("--iterations", sp.quickstep_iterations, "SimParams.quickstep_iterations");
  app.add_option("--max-linear-acceleration", sp.max_linear_acceleration, "SimParams.max_linear_acceleration");
  app.add_option("--max-angular-acceleration", sp.max_angular_acceleration, "SimParams.max_angular_acceleration");
  app.add_option("--spin-threshold", sp.rolling_spin_threshold, "SimParams.rolling_spin_threshold");
  app.add_flag("--bench", bench, "time whole episodes of random robots with exactly N spheres instead");
  app.add_option("--bench-sizes", bench_sizes, "sphere counts for --bench");
  app.add_option("--bench-robots", bench_robots, "robots per size for --bench");
  app.set_version_flag("--version", robozoo::version_line());
  if (const auto stop = robozoo::parse_options(app, argc, argv, "robozoo-simstats")) return *stop;

  Rng rng(seed);
  if (bench) {
    std::printf("%8s %8s %12s %12s %12s %10s\n", "spheres", "bodies", "steps/s", "bare_steps/s", "physics%",
                "s/episode");
    for (int n : bench_sizes) {
      RandomRobotParams p = rp;
      p.min_spheres = p.max_spheres = n;
      double t_sim = 0, t_bare = 0, phys = 0, bodies = 0;
      long steps = 0, bare_steps = 0;
      for (int i = 0; i < bench_robots; ++i) {
        const Robot r = random_robot(rng, p);
        bodies += r.num_bodies;
        SimParams q = sp;
        q.max_linear_acceleration = q.max_angular_acceleration = INFINITY;
        q.rest_steps = q.steps + 1;  // time full episodes
        Simulation sim(r, q);
        sim.enable_timing(true);
        const auto t0 = std::chrono::steady_clock::now();
        while (sim.step()) {
        }
        const auto t1 = std::chrono::steady_clock::now();
        simulate_bare(r, q, q.steps);
        const auto t2 = std::chrono::steady_clock::now();
        t_sim += std::chrono::duration<double>(t1 - t0).count();
        t_bare += std::chrono::duration<double>(t2 - t1).count();
        phys += sim.timing().physics;
        steps += sim.state().step;
        bare_steps += q.steps;
      }
      std::printf("%8d %8.1f %12.0f %12.0f %11.0f%% %10.4f\n", n, bodies / bench_robots, steps / t_sim,
                  bare_steps / t_bare, 100 * phys / t_sim, t_sim / bench_robots);
    }
    return 0;
  }

  std::ofstream out;
  if (!csv.empty()) {
    out.open(csv);
    out << "robot,spheres,bodies,joints,outcome,steps_run,stopped_early,d_raw,max_lin_acc,max_ang_acc,"
           "max_mean_ang_speed,max_contact_fraction,max_body_z\n";
  }
  std::map<Outcome, int> counts;
  int would_contact = 0, would_spin = 0, stable = 0, stopped_early = 0, movers_contact = 0;
  std::vector<double> spin_stable_movers, lin_acc, ang_acc;
  double t_total = 0;
  long steps_total = 0;
  for (int i = 0; i < robots; ++i) {
    const Robot r = random_robot(rng, rp);
    Simulation sim(r, sp);
    double max_z = 0;
    const auto t0 = std::chrono::steady_clock::now();
    while (sim.step())
      for (const auto& p : sim.state().body_position) max_z = std::max(max_z, p.z());
    t_total += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    steps_total += sim.state().step;
    const SimResult res = sim.result();
    ++counts[res.outcome];
    stopped_early += res.stopped_early;
    const double spin = res.mean_angular_speed.empty()
                            ? 0
                            : *std::max_element(res.mean_angular_speed.begin(), res.mean_angular_speed.end());
    const double contact = *std::max_element(res.ground_contact_fraction.begin(), res.ground_contact_fraction.end());
    if (res.outcome != Outcome::AccelFault) {
      ++stable;
      lin_acc.push_back(res.max_linear_acceleration);
      ang_acc.push_back(res.max_angular_acceleration);
      if (contact > sp.rolling_contact_fraction) ++would_contact;
      if (spin > sp.rolling_spin_threshold) ++would_spin;
      if (std::abs(res.d_raw) > 0.05) {
        spin_stable_movers.push_back(spin);
        if (contact > sp.rolling_contact_fraction) ++movers_contact;
      }
    }
    if (out)
      out << i << ',' << r.spheres.size() << ',' << r.num_bodies << ',' << r.joints.size() << ','
          << outcome_name(res.outcome) << ',' << res.steps_run << ',' << res.stopped_early << ',' << res.d_raw << ','
          << res.max_linear_acceleration << ',' << res.max_angular_acceleration << ',' << spin << ',' << contact << ','
          << max_z << '\n';
  }
  std::printf("robots %d (spheres %d-%d), %.0f steps/s overall\n", robots, rp.min_spheres, rp.max_spheres,
              steps_total / t_total);
  for (int o = 0; o < kNumOutcomes; ++o)
    std::printf("  %-16s %5.1f%%\n", outcome_name(static_cast<Outcome>(o)).c_str(),
                100.0 * counts[static_cast<Outcome>(o)] / robots);
  std::printf("not faulted: %d; of them rule (i) fires on %.1f%%, rule (ii) alone would fire on %.1f%%\n", stable,
              100.0 * would_contact / std::max(1, stable), 100.0 * would_spin / std::max(1, stable));
  std::printf("stopped early (any outcome): %.1f%%; movers failing rule (i): %d of %zu\n",
              100.0 * stopped_early / robots, movers_contact, spin_stable_movers.size());
  std::printf("not faulted: max linear acc median %.1f, 95%% %.1f, max %.1f m/s^2\n", median(lin_acc),
              quantile(lin_acc, 0.95), quantile(lin_acc, 1.0));
  std::printf("not faulted: max angular acc median %.1f, 95%% %.1f, max %.1f rad/s^2\n", median(ang_acc),
              quantile(ang_acc, 0.95), quantile(ang_acc, 1.0));
  std::printf(
      "movers (|d_raw| > 0.05 m, %zu): worst-body mean angular speed median %.3f, 90%% %.3f, "
      "95%% %.3f, max %.3f rad/s\n",
      spin_stable_movers.size(), median(spin_stable_movers), quantile(spin_stable_movers, 0.9),
      quantile(spin_stable_movers, 0.95), quantile(spin_stable_movers, 1.0));
  return 0;
}
