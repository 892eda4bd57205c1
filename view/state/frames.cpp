#include "view/state/frames.hpp"

#include <cmath>

#include "evolve/core/version.hpp"
#include "runlog/robots/leaf_spheres.hpp"

namespace robozoo::view {

namespace {

// Divided by the integer scale rather than multiplied by the unit: the result is
// the double nearest the decimal (0.2342, not 0.23420000000000002), which JSON
// writes in the fewest digits.
double round_to(double v, double per_unit) { return std::isfinite(v) ? std::round(v * per_unit) / per_unit : 0.0; }

constexpr double kPositionUnit = 1e4;  // per m: 0.1 mm
constexpr double kValueUnit = 1e4;     // per unit of neuron and sensor values: 1e-4

nlohmann::json values(const std::vector<double>& v) {
  nlohmann::json a = nlohmann::json::array();
  for (double x : v) a.push_back(round_to(x, kValueUnit));
  return a;
}

template <class Points>
nlohmann::json flat_points(const Points& pts) {
  nlohmann::json a = nlohmann::json::array();
  for (const auto& p : pts)
    for (int k = 0; k < 3; ++k) a.push_back(round_to(p[k], kPositionUnit));
  return a;
}

/// The CPPN as the page draws it: nodes with their drawing positions, links
/// with their weights (disabled ones too, marked).
nlohmann::json cppn_json(const cppn_genome_t& g) {
  nlohmann::json nodes = nlohmann::json::array(), links = nlohmann::json::array();
  for (const cppn_node_t& n : g.nodes)
    nodes.push_back({{"id", n.id}, {"kind", n.kind}, {"act", n.activation}, {"pos", n.position}});
  for (const link_t& l : g.links)
    links.push_back({{"inn", l.innovation},
                     {"from", l.from_node},
                     {"to", l.to_node},
                     {"w", round_to(l.weight, kValueUnit)},
                     {"on", l.enabled != 0}});
  return {{"nodes", nodes}, {"links", links}};
}

}  // namespace

Frame make_frame(const nlohmann::json& j) { return std::make_shared<const std::string>(j.dump()); }

nlohmann::json hello_json(const std::string& mode, const std::string& source) {
  return {{"t", "hello"}, {"mode", mode}, {"source", source}, {"version", software_version_string()}};
}

nlohmann::json run_json(const run_t& run, const double target[3]) {
  return {{"t", "run"},
          {"id", run.run_id},
          {"regime", run.regime == 1 ? "recurrent" : "feedforward"},
          {"seed", run.seed},
          {"population", run.population},
          {"generations", run.generations},
          {"steps", run.steps},
          {"dt", run.dt},
          {"target", {target[0], target[1], target[2]}},
          {"version", run.software_version}};
}

nlohmann::json generation_json(const generation_t& g) {
  return {{"t", "gen"},
          {"g", g.generation},
          {"best", g.best_fitness},
          {"mean", g.mean_fitness},
          {"bsf", g.best_so_far_fitness},
          {"species", g.num_species},
          {"evaluations", g.evaluations},
          {"eval_s", g.eval_seconds},
          {"gen_s", g.generation_seconds},
          {"champion", g.champion_id},
          {"outcomes",
           {{"not_simulated", g.n_not_simulated},
            {"completed", g.n_completed},
            {"stopped_early", g.n_stopped_early},
            {"accel_fault", g.n_accel_fault},
            {"rolling_contact", g.n_rolling_contact},
            {"rolling_spin", g.n_rolling_spin}}}};
}

nlohmann::json champion_json(const cppn_genome_t& g) {
  return {{"t", "champion"}, {"id", g.genome_id}, {"gen", g.generation}, {"fitness", g.fitness}};
}

nlohmann::json robot_json(const cppn_genome_t& g, const morphology_t& m, bool live, bool replay) {
  nlohmann::json radius = nlohmann::json::array(), leaf = nlohmann::json::array(), start = nlohmann::json::array(),
                 types = nlohmann::json::array();
  const std::vector<bool> leaves = leaf_spheres(m);
  for (size_t i = 0; i < m.spheres.size(); ++i) {
    radius.push_back(round_to(m.spheres[i].radius, kPositionUnit));
    leaf.push_back(leaves[i] ? 1 : 0);
    for (int k = 0; k < 3; ++k) start.push_back(round_to(m.spheres[i].center[k], kPositionUnit));
  }
  for (int8_t t : m.sensor_type) types.push_back(t);
  nlohmann::json sensor_sphere = nlohmann::json::array();
  for (int32_t s : m.sensor_sphere) sensor_sphere.push_back(s);
  return {{"t", "robot"},
          {"id", g.genome_id},
          {"gen", g.generation},
          {"fitness", g.fitness},
          {"radius", radius},
          {"leaf", leaf},
          {"start", start},
          {"sensor_type", types},
          {"sensor_sphere", sensor_sphere},
          {"neurons", m.num_neurons},
          {"sensors", m.num_sensors},
          {"live", live},
          {"replay", replay},
          {"cppn", cppn_json(g)}};
}

nlohmann::json pose_json(const pose_t& p) {
  return {{"t", "pose"},
          {"id", p.genome_id},
          {"step", p.step},
          {"time", p.sim_time},
          {"utime", p.utime},
          {"c", flat_points(p.sphere_center)},
          {"n", values(p.neuron_output)},
          {"s", values(p.sensor_value)}};
}

nlohmann::json trajectory_json(int64_t genome_id, const Trajectory& t) {
  nlohmann::json list = nlohmann::json::array();
  for (size_t i = 0; i < t.time.size(); ++i)
    list.push_back({{"step", t.step[i]},
                    {"time", t.time[i]},
                    {"c", flat_points(t.centers[i])},
                    {"n", i < t.neurons.size() ? values(t.neurons[i]) : nlohmann::json::array()},
                    {"s", i < t.sensors.size() ? values(t.sensors[i]) : nlohmann::json::array()}});
  return {{"t", "poses"}, {"id", genome_id}, {"list", list}, {"done", true}, {"resimulated", t.resimulated}};
}

}  // namespace robozoo::view
