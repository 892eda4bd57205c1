#include "runlog/text/message_json.hpp"

#include "evolve/messages/build.hpp"
#include "evolve/messages/safe_decode.hpp"

namespace robozoo {

namespace {

nlohmann::json fields(const run_t& m) {
  return {
      {"utime", m.utime},   {"run_id", m.run_id},          {"software_version", m.software_version}, {"seed", m.seed},
      {"regime", m.regime}, {"population", m.population},  {"generations", m.generations},           {"steps", m.steps},
      {"dt", m.dt},         {"config_json", m.config_json}};
}

nlohmann::json fields(const generation_t& m) {
  return {{"utime", m.utime},
          {"run_id", m.run_id},
          {"generation", m.generation},
          {"evaluations", m.evaluations},
          {"best_fitness", m.best_fitness},
          {"mean_fitness", m.mean_fitness},
          {"stderr_fitness", m.stderr_fitness},
          {"best_so_far_fitness", m.best_so_far_fitness},
          {"champion_id", m.champion_id},
          {"num_species", m.num_species},
          {"compatibility_threshold", m.compatibility_threshold},
          {"n_not_simulated", m.n_not_simulated},
          {"n_completed", m.n_completed},
          {"n_stopped_early", m.n_stopped_early},
          {"n_accel_fault", m.n_accel_fault},
          {"n_rolling_contact", m.n_rolling_contact},
          {"n_rolling_spin", m.n_rolling_spin},
          {"eval_seconds", m.eval_seconds},
          {"generation_seconds", m.generation_seconds}};
}

nlohmann::json fields(const cppn_genome_t& m) {
  nlohmann::json nodes = nlohmann::json::array(), links = nlohmann::json::array();
  for (const cppn_node_t& n : m.nodes)
    nodes.push_back({{"id", n.id}, {"kind", n.kind}, {"activation", n.activation}, {"position", n.position}});
  for (const link_t& l : m.links)
    links.push_back({{"innovation", l.innovation},
                     {"from_node", l.from_node},
                     {"to_node", l.to_node},
                     {"weight", l.weight},
                     {"enabled", l.enabled != 0}});
  return {{"utime", m.utime},
          {"run_id", m.run_id},
          {"generation", m.generation},
          {"genome_id", m.genome_id},
          {"species_id", m.species_id},
          {"fitness", m.fitness},
          {"r_term", m.r_term},
          {"d_term", m.d_term},
          {"outcome", m.outcome},
          {"num_nodes", m.num_nodes},
          {"nodes", nodes},
          {"num_links", m.num_links},
          {"links", links}};
}

nlohmann::json fields(const morphology_t& m) {
  nlohmann::json spheres = nlohmann::json::array();
  for (const sphere_t& s : m.spheres)
    spheres.push_back({{"index", s.index},
                       {"parent", s.parent},
                       {"center", {s.center[0], s.center[1], s.center[2]}},
                       {"radius", s.radius},
                       {"density", s.density},
                       {"body", s.body},
                       {"has_joint", s.has_joint != 0},
                       {"joint_axis", {s.joint_axis[0], s.joint_axis[1], s.joint_axis[2]}},
                       {"joint_range", s.joint_range},
                       {"motor_neuron", s.motor_neuron},
                       {"sensors", s.sensors}});
  return {{"utime", m.utime},
          {"run_id", m.run_id},
          {"generation", m.generation},
          {"genome_id", m.genome_id},
          {"num_spheres", m.num_spheres},
          {"spheres", spheres},
          {"num_bodies", m.num_bodies},
          {"num_neurons", m.num_neurons},
          {"tau", m.tau},
          {"omega", m.omega},
          {"num_sensors", m.num_sensors},
          {"sensor_sphere", m.sensor_sphere},
          {"sensor_type", m.sensor_type},
          {"w_sensor_neuron", m.w_sensor_neuron},
          {"w_neuron_neuron", m.w_neuron_neuron},
          {"r_term", m.r_term}};
}

nlohmann::json fields(const pose_t& m) {
  return {{"utime", m.utime},
          {"run_id", m.run_id},
          {"generation", m.generation},
          {"genome_id", m.genome_id},
          {"step", m.step},
          {"sim_time", m.sim_time},
          {"num_bodies", m.num_bodies},
          {"body_position", m.body_position},
          {"body_quaternion", m.body_quaternion},
          {"num_spheres", m.num_spheres},
          {"sphere_center", m.sphere_center},
          {"num_neurons", m.num_neurons},
          {"neuron_output", m.neuron_output},
          {"num_sensors", m.num_sensors},
          {"sensor_value", m.sensor_value}};
}

template <class T>
bool convert(const void* data, size_t size, nlohmann::json& out, std::string& why) {
  T m{};
  if (!safe_decode(data, size, m, &why)) return false;
  out = fields(m);
  return true;
}

}  // namespace

bool message_to_json(const std::string& channel, const void* data, size_t size, nlohmann::json& out, std::string& why) {
  why.clear();
  if (channel == kChannelRun) return convert<run_t>(data, size, out, why);
  if (channel == kChannelGeneration) return convert<generation_t>(data, size, out, why);
  if (channel == kChannelGenome) return convert<cppn_genome_t>(data, size, out, why);
  if (channel == kChannelMorphology) return convert<morphology_t>(data, size, out, why);
  if (channel == kChannelPose) return convert<pose_t>(data, size, out, why);
  return false;
}

}  // namespace robozoo
