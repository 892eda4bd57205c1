#include "evolve/messages/build.hpp"

#include "evolve/core/version.hpp"

#include <stdexcept>

namespace robozoo {

std::string software_version() { return software_version_string(); }

run_t make_run_message(const std::string& run_id, const RunConfig& config, int64_t utime) {
  run_t m{};
  m.utime = utime;
  m.run_id = run_id;
  m.software_version = software_version();
  m.seed = config.seed;
  m.regime = static_cast<int8_t>(config.regime);
  m.population = config.neat.population;
  m.generations = config.generations;
  m.steps = config.eval.sim.steps;
  m.dt = config.eval.sim.dt;
  m.config_json = config_to_json(config).dump();
  return m;
}

generation_t make_generation_message(const std::string& run_id, const GenerationSummary& s, int64_t utime) {
  generation_t m{};
  m.utime = utime;
  m.run_id = run_id;
  m.generation = s.generation;
  m.evaluations = s.evaluations;
  m.best_fitness = s.best_fitness;
  m.mean_fitness = s.mean_fitness;
  m.stderr_fitness = s.stderr_fitness;
  m.best_so_far_fitness = s.best_so_far_fitness;
  m.champion_id = s.champion_id;
  m.num_species = s.num_species;
  m.compatibility_threshold = s.compatibility_threshold;
  m.n_not_simulated = s.outcome_counts[0];
  m.n_completed = s.outcome_counts[1];
  m.n_stopped_early = s.outcome_counts[2];
  m.n_accel_fault = s.outcome_counts[3];
  m.n_rolling_contact = s.outcome_counts[4];
  m.n_rolling_spin = s.outcome_counts[5];
  m.eval_seconds = s.eval_seconds;
  m.generation_seconds = s.generation_seconds;
  return m;
}

cppn_genome_t make_genome_message(const std::string& run_id, int32_t generation, const Genome& g, int32_t species_id,
                                  const GenomeScore& score, int64_t utime) {
  cppn_genome_t m{};
  m.utime = utime;
  m.run_id = run_id;
  m.generation = generation;
  m.genome_id = g.id;
  m.species_id = species_id;
  m.fitness = score.fitness;
  m.r_term = score.r;
  m.d_term = score.d;
  m.outcome = static_cast<int8_t>(score.outcome);
  m.num_nodes = static_cast<int32_t>(g.nodes.size());
  m.nodes.reserve(g.nodes.size());
  for (const auto& n : g.nodes) {
    cppn_node_t x{};
    x.id = n.id;
    x.kind = static_cast<int8_t>(n.kind);
    x.activation = static_cast<int8_t>(n.activation);
    x.position = n.position;
    m.nodes.push_back(x);
  }
  m.num_links = static_cast<int32_t>(g.links.size());
  m.links.reserve(g.links.size());
  for (const auto& l : g.links) {
    link_t x{};
    x.innovation = l.innovation;
    x.from_node = l.from;
    x.to_node = l.to;
    x.weight = l.weight;
    x.enabled = l.enabled;
    m.links.push_back(x);
  }
  return m;
}

morphology_t make_morphology_message(const std::string& run_id, int32_t generation, int64_t genome_id,
                                     const Robot& robot, int64_t utime) {
  morphology_t m{};
  m.utime = utime;
  m.run_id = run_id;
  m.generation = generation;
  m.genome_id = genome_id;
  m.num_spheres = static_cast<int32_t>(robot.spheres.size());
  for (const auto& s : robot.spheres) {
    sphere_t x{};
    x.index = s.index;
    x.parent = s.parent;
    for (int k = 0; k < 3; ++k) {
      x.center[k] = s.center[k];
      x.joint_axis[k] = s.has_joint ? s.joint_axis[k] : 0.0;
    }
    x.radius = s.radius;
    x.density = s.density;
    x.body = s.body;
    x.has_joint = s.has_joint;
    x.joint_range = s.has_joint ? s.joint_range : 0.0;
    x.motor_neuron = s.motor_neuron;
    x.sensors = static_cast<int8_t>(s.sensors);
    m.spheres.push_back(x);
  }
  m.num_bodies = robot.num_bodies;
  m.num_neurons = static_cast<int32_t>(robot.neurons.size());
  for (const auto& n : robot.neurons) {
    m.tau.push_back(n.tau);
    m.omega.push_back(n.omega);
  }
  m.num_sensors = static_cast<int32_t>(robot.sensors.size());
  for (const auto& s : robot.sensors) {
    m.sensor_sphere.push_back(s.sphere);
    m.sensor_type.push_back(static_cast<int8_t>(s.type));
  }
  const int ns = m.num_sensors, nn = m.num_neurons;
  m.w_sensor_neuron.assign(ns, std::vector<double>(nn, 0.0));
  for (int k = 0; k < ns; ++k)
    for (int i = 0; i < nn; ++i) m.w_sensor_neuron[k][i] = robot.w_sensor_neuron(k, i);
  m.w_neuron_neuron.assign(nn, std::vector<double>(nn, 0.0));
  for (int j = 0; j < nn; ++j)
    for (int i = 0; i < nn; ++i) m.w_neuron_neuron[j][i] = robot.w_neuron_neuron(j, i);
  m.r_term = robot.r_term;
  return m;
}

pose_t make_pose_message(const std::string& run_id, int32_t generation, int64_t genome_id, const SimState& s,
                         int64_t utime) {
  pose_t m{};
  m.utime = utime;
  m.run_id = run_id;
  m.generation = generation;
  m.genome_id = genome_id;
  m.step = s.step;
  m.sim_time = s.time;
  m.num_bodies = static_cast<int32_t>(s.body_position.size());
  for (size_t b = 0; b < s.body_position.size(); ++b) {
    const auto& p = s.body_position[b];
    const auto& q = s.body_quaternion[b];
    m.body_position.push_back({p[0], p[1], p[2]});
    m.body_quaternion.push_back({q[0], q[1], q[2], q[3]});
  }
  m.num_spheres = static_cast<int32_t>(s.sphere_center.size());
  for (const auto& c : s.sphere_center) m.sphere_center.push_back({c[0], c[1], c[2]});
  m.num_neurons = static_cast<int32_t>(s.neuron_output.size());
  m.neuron_output = s.neuron_output;
  m.num_sensors = static_cast<int32_t>(s.sensor_value.size());
  m.sensor_value = s.sensor_value;
  return m;
}

Genome genome_from_message(const cppn_genome_t& m, const GenomeLayout& layout) {
  if (m.num_nodes < 0 || static_cast<size_t>(m.num_nodes) != m.nodes.size() || m.num_links < 0 ||
      static_cast<size_t>(m.num_links) != m.links.size())
    throw std::invalid_argument("genome message " + std::to_string(m.genome_id) + ": counts do not match its arrays");
  Genome g;
  g.id = m.genome_id;
  for (const auto& n : m.nodes) {
    if (n.kind < 0 || n.kind > 3)
      throw std::invalid_argument("genome " + std::to_string(m.genome_id) + ": node " + std::to_string(n.id) +
                                  " has unknown kind " + std::to_string(n.kind));
    if (!valid_activation(n.activation))
      throw std::invalid_argument("genome " + std::to_string(m.genome_id) + ": node " + std::to_string(n.id) +
                                  " has unknown activation " + std::to_string(n.activation));
    g.nodes.push_back({n.id, static_cast<NodeKind>(n.kind), static_cast<Activation>(n.activation), n.position});
  }
  for (const auto& l : m.links) g.links.push_back({l.innovation, l.from_node, l.to_node, l.weight, l.enabled != 0, 0});
  validate_genome(g, layout);
  return g;
}

}  // namespace robozoo
