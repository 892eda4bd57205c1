#include "evolve/app/eval_command.hpp"

#include <fstream>
#include <iostream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "evolve/config/run_config.hpp"
#include "evolve/cppn/network.hpp"
#include "evolve/fitness/evaluate.hpp"
#include "evolve/growth/growth.hpp"
#include "evolve/neat/population_json.hpp"
#include "evolve/neat/start/random_genome.hpp"

namespace robozoo {

void add_eval_options(CLI::App& app, EvalOptions& o) {
  app.add_option("--random", o.random_seed,
                 "seed of a random genome: an initial genome after --mutations rounds "
                 "of NEAT mutations (default 1)");
  app.add_option("--regime", o.regime, "regime of the random genome's mutations")
      ->check(CLI::IsMember({"feedforward", "recurrent"}));
  app.add_option("--mutations", o.mutations, "mutation rounds of the random genome")->check(CLI::Range(0, 100000));
  app.add_option("--genome", o.genome_file, "a genome JSON file (as --save-genome writes) instead of a random one");
  app.add_option("--save-genome", o.save_genome, "write the genome evaluated to this JSON file");
  app.add_option("--config", o.config_file, "configuration file (.json or .toml)");
  app.add_option("--steps", o.steps, "physics steps (default: the configuration's)")->check(CLI::Range(1, 1000000000));
  app.add_flag("--json", o.json, "print the result as JSON");
}

namespace {

nlohmann::json describe(const Genome& g, const Robot& robot, const Evaluation& e) {
  int per_type[4] = {0, 0, 0, 0};
  for (const auto& s : robot.sensors) ++per_type[static_cast<int>(s.type)];
  int leaves = 0;
  for (const auto& s : robot.spheres) leaves += s.num_children == 0;
  int nn_links = 0, sn_links = 0;
  for (int i = 0; i < robot.w_neuron_neuron.size(); ++i) nn_links += robot.w_neuron_neuron.data()[i] != 0.0;
  for (int i = 0; i < robot.w_sensor_neuron.size(); ++i) sn_links += robot.w_sensor_neuron.data()[i] != 0.0;
  nlohmann::json j;
  j["genome"] = {{"id", g.id},
                 {"nodes", g.nodes.size()},
                 {"hidden_nodes", count_hidden(g)},
                 {"links", g.links.size()},
                 {"enabled_links", count_enabled_links(g)},
                 {"cyclic", has_cycle(g)}};
  j["morphology"] = {
      {"spheres", robot.spheres.size()},
      {"leaves", leaves},
      {"bodies", robot.num_bodies},
      {"joints", robot.joints.size()},
      {"neurons", robot.neurons.size()},
      {"sensors",
       {{"distance", per_type[0]}, {"touch", per_type[1]}, {"proprioceptive", per_type[2]}, {"time", per_type[3]}}},
      {"neuron_neuron_links", nn_links},
      {"sensor_neuron_links", sn_links}};
  j["r"] = e.r;
  j["simulated"] = e.outcome != Outcome::NotSimulated;
  j["outcome"] = outcome_name(e.outcome);
  j["d"] = e.d;
  j["fitness"] = e.fitness;
  if (e.outcome != Outcome::NotSimulated) {
    double max_contact = 0, max_spin = 0;
    for (double x : e.sim.ground_contact_fraction) max_contact = std::max(max_contact, x);
    for (double x : e.sim.mean_angular_speed) max_spin = std::max(max_spin, x);
    j["simulation"] = {{"steps_run", e.sim.steps_run},
                       {"d_init", e.sim.d_init},
                       {"d_final", e.sim.d_final},
                       {"max_ground_contact_fraction", max_contact},
                       {"max_mean_angular_speed", max_spin},
                       {"max_linear_acceleration", e.sim.max_linear_acceleration},
                       {"max_angular_acceleration", e.sim.max_angular_acceleration}};
  }
  return j;
}

}  // namespace

int run_eval_command(const EvalOptions& o) {
  RunConfig config;
  Genome genome;
  try {
    if (!o.config_file.empty()) config = load_config_file(o.config_file);
    if (o.steps > 0) config.eval.sim.steps = o.steps;
    validate_config(config);
    if (!o.genome_file.empty()) {
      std::ifstream in(o.genome_file);
      if (!in) throw std::invalid_argument(o.genome_file + ": cannot read the genome file");
      nlohmann::json j;
      try {
        in >> j;
      } catch (const nlohmann::json::exception& e) {
        throw std::invalid_argument(o.genome_file + ": not valid JSON (" + e.what() + ")");
      }
      genome = genome_from_json(j, o.genome_file);
      validate_genome(genome, robot_layout());
    } else {
      Rng rng(static_cast<uint64_t>(o.random_seed));
      RandomGenomeParams rp;
      rp.rounds = o.mutations;
      genome = random_evolved_genome(robot_layout(), regime_from_name(o.regime), config.neat, rp, rng);
    }
    if (!o.save_genome.empty()) {
      std::ofstream out(o.save_genome);
      out << genome_to_json(genome).dump(2) << "\n";
      if (!out) throw std::invalid_argument(o.save_genome + ": cannot write the genome file");
    }
  } catch (const std::exception& e) {
    std::cerr << "robozoo-evolve eval: " << e.what() << "\n";
    return 2;
  }
  const Robot robot = grow_genome(genome, config.eval);
  const Evaluation e = evaluate(genome, config.eval);
  const nlohmann::json j = describe(genome, robot, e);
  if (o.json) {
    std::cout << j.dump(2) << "\n";
    return 0;
  }
  const auto& m = j["morphology"];
  std::cout << "genome   " << genome.id << ": " << j["genome"]["nodes"] << " nodes (" << j["genome"]["hidden_nodes"]
            << " hidden), " << j["genome"]["enabled_links"] << " enabled links"
            << (j["genome"]["cyclic"].get<bool>() ? ", cyclic" : "") << "\n"
            << "robot    " << m["spheres"] << " spheres (" << m["leaves"] << " leaves), " << m["bodies"]
            << " rigid bodies, " << m["joints"] << " joints\n"
            << "sensors  distance " << m["sensors"]["distance"] << ", touch " << m["sensors"]["touch"]
            << ", proprioceptive " << m["sensors"]["proprioceptive"] << ", time " << m["sensors"]["time"] << "\n"
            << "ctrnn    " << m["neurons"] << " neurons, " << m["neuron_neuron_links"] << " neuron-neuron and "
            << m["sensor_neuron_links"] << " sensor-neuron links\n"
            << "outcome  " << j["outcome"].get<std::string>() << "\n"
            << "fitness  " << e.fitness << " = r " << e.r << " + d " << e.d << "\n";
  if (j.contains("simulation"))
    std::cout << "sim      " << j["simulation"]["steps_run"] << " steps, max ground contact "
              << j["simulation"]["max_ground_contact_fraction"] << ", max mean angular speed "
              << j["simulation"]["max_mean_angular_speed"] << " rad/s\n";
  return 0;
}

}  // namespace robozoo
