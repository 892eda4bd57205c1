// robozoo-gen0: what generation 0 of each arm grows, before any selection. The
// initial genomes of each arm (its start topology with random weights) are grown
// by the real growth code, and the shares of robots beyond the root, with a
// joint, with a joint and a distance sensor, and earning simulation are printed
// (a check of the prediction that HyperNEAT's fully recurrent start gives the
// experimental regime a head start).
#include <CLI/CLI.hpp>

#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

#include "study/analysis/measure/initial_robots.hpp"
#include "evolve/core/version.hpp"
#include "study/experiment/trial_plan.hpp"
#include "util/parse_options.hpp"

using namespace robozoo;

int main(int argc, char** argv) {
  CLI::App app{
      "robozoo-gen0: grow N generation-0 genomes of each arm (feedforward: 99 links; recurrent: 209; "
      "recurrent-sparse: recurrence allowed, 99 links; recurrent-zero: 209 links, the 110 output-to-output ones "
      "at weight 0) with the default configuration and print what share "
      "grows beyond the root, has a joint, a joint and a distance sensor, and earns simulation."};
  int64_t genomes = 1000;
  uint64_t seed = 1;
  bool json = false;
  std::string config_file;
  app.add_option("--genomes,-n", genomes, "genomes per arm")->check(CLI::Range(int64_t{1}, int64_t{100000000}));
  app.add_option("--seed", seed, "seed of the weights (the same for every arm)");
  app.add_option("--config", config_file, "configuration file (.json or .toml) over the defaults");
  app.add_flag("--json", json, "print JSON");
  app.set_version_flag("--version", robozoo::version_line());
  if (const auto stop = robozoo::parse_options(app, argc, argv, "robozoo-gen0")) return *stop;

  RunConfig base;
  try {
    if (!config_file.empty()) base = load_config_file(config_file, base);
  } catch (const std::exception& e) {
    std::cerr << "robozoo-gen0: " << e.what() << "\n";
    return 2;
  }
  nlohmann::json out = nlohmann::json::array();
  if (!json)
    std::printf("%-17s %7s %6s %12s %11s %16s %10s %8s\n", "arm", "genomes", "links", "beyond root", "with joint",
                "joint+distance", "simulated", "spheres");
  for (Arm arm : {Arm::FeedForward, Arm::Recurrent, Arm::RecurrentSparse, Arm::RecurrentZero}) {
    RunConfig c = base;
    c.regime = arm_regime(arm);
    c.neat.initial_links = arm_initial_links(arm);
    std::cerr << "robozoo-gen0: growing " << genomes << " generation-0 genomes of " << arm_name(arm) << "\n";
    const InitialRobotShares s = initial_robot_shares(c, genomes, seed);
    const double n = static_cast<double>(s.genomes);
    if (json) {
      out.push_back({{"arm", arm_name(arm)},
                     {"genomes", s.genomes},
                     {"mean_links", s.mean_links},
                     {"beyond_root", s.beyond_root},
                     {"with_joint", s.with_joint},
                     {"joint_and_distance", s.joint_and_distance},
                     {"simulated", s.simulated},
                     {"mean_spheres", s.mean_spheres}});
    } else {
      std::printf("%-17s %7lld %6.0f %11.1f%% %10.1f%% %15.1f%% %9.1f%% %8.2f\n", arm_name(arm).c_str(),
                  static_cast<long long>(s.genomes), s.mean_links, 100.0 * s.beyond_root / n, 100.0 * s.with_joint / n,
                  100.0 * s.joint_and_distance / n, 100.0 * s.simulated / n, s.mean_spheres);
    }
  }
  if (json) std::cout << out.dump(2) << "\n";
  return 0;
}
