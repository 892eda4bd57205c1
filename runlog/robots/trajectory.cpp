#include "runlog/robots/trajectory.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "evolve/config/run_config.hpp"
#include "evolve/messages/log_continuation.hpp"
#include "evolve/sim/episode/simulation.hpp"
#include "evolve/sim/episode/trajectory_sampler.hpp"
#include "runlog/robots/regrow.hpp"
#include "runlog/robots/selection.hpp"

namespace robozoo {

std::vector<Eigen::Vector3d> Trajectory::sample(double t) const {
  if (empty()) throw std::logic_error("Trajectory::sample on an empty trajectory");
  if (t <= time.front()) return centers.front();
  if (t >= time.back()) return centers.back();
  const size_t hi = static_cast<size_t>(std::upper_bound(time.begin(), time.end(), t) - time.begin());
  const size_t lo = hi - 1;
  const double a = (t - time[lo]) / (time[hi] - time[lo]);
  std::vector<Eigen::Vector3d> out(centers[lo].size());
  for (size_t i = 0; i < out.size(); ++i) out[i] = centers[lo][i] + a * (centers[hi][i] - centers[lo][i]);
  return out;
}

Trajectory trajectory_from_poses(const std::vector<pose_t>& poses, size_t num_spheres) {
  if (poses.empty()) throw std::invalid_argument("no poses");
  Trajectory tr;
  for (const pose_t& p : poses) {
    if (p.sphere_center.size() != num_spheres || static_cast<size_t>(p.num_spheres) != num_spheres)
      throw std::invalid_argument("pose at step " + std::to_string(p.step) + " has " +
                                  std::to_string(p.sphere_center.size()) + " spheres, the robot " +
                                  std::to_string(num_spheres));
    if (!tr.time.empty() && !(p.sim_time > tr.time.back()))
      throw std::invalid_argument("pose times do not increase at step " + std::to_string(p.step));
    tr.step.push_back(p.step);
    tr.time.push_back(p.sim_time);
    std::vector<Eigen::Vector3d> c;
    c.reserve(num_spheres);
    for (const auto& v : p.sphere_center) c.emplace_back(v[0], v[1], v[2]);
    tr.centers.push_back(std::move(c));
    tr.neurons.push_back(p.neuron_output);
    tr.sensors.push_back(p.sensor_value);
  }
  return tr;
}

Trajectory simulate_trajectory(const run_t& run, const cppn_genome_t& genome, const morphology_t& morphology,
                               int every) {
  if (every < 1) throw std::invalid_argument("simulate_trajectory: every must be >= 1");
  RunConfig config;
  try {
    config = config_from_record(nlohmann::json::parse(split_run_config(run.config_json).config_json));
  } catch (const nlohmann::json::exception& e) {
    throw std::invalid_argument("run " + run.run_id + ": its configuration is not JSON: " + e.what());
  }
  const RegrownGenome regrown = regrow_genome(genome, config);
  require_logged_morphology(regrown.robot, morphology, genome.genome_id);
  Simulation sim(regrown.robot, config.eval.sim);
  Trajectory tr;
  tr.resimulated = true;
  sample_trajectory(sim, every, [&](const SimState& s) {
    tr.step.push_back(s.step);
    tr.time.push_back(s.time);
    tr.centers.push_back(s.sphere_center);
    tr.neurons.push_back(s.neuron_output);
    tr.sensors.push_back(s.sensor_value);
  });
  return tr;
}

Trajectory genome_trajectory(const RunRecord& run, const GenomeRecord& genome, bool resimulate, int every) {
  if (!genome.has_morphology)
    throw std::invalid_argument("genome " + std::to_string(genome.genome.genome_id) + " has no logged morphology");
  if (!resimulate)
    if (const GenomeRecord* source = logged_pose_source(run, genome))
      return trajectory_from_poses(source->poses, genome.morphology.spheres.size());
  return simulate_trajectory(run.run, genome.genome, genome.morphology, every);
}

const GenomeRecord* logged_pose_source(const RunRecord& run, const GenomeRecord& genome) {
  if (!genome.poses.empty()) return &genome;
  const uint64_t genes = gene_hash(genome.genome);
  for (const auto& other : run.genomes)
    if (other.get() != &genome && !other->poses.empty() && other->has_morphology &&
        other->morphology.num_spheres == genome.morphology.num_spheres && gene_hash(other->genome) == genes)
      return other.get();
  return nullptr;
}

Eigen::Vector3d run_target(const run_t& run) {
  try {
    const RunConfig c = config_from_record(nlohmann::json::parse(split_run_config(run.config_json).config_json));
    return {c.eval.sim.target_x, c.eval.sim.target_y, c.eval.sim.target_z};
  } catch (const std::exception& e) {
    throw std::invalid_argument("run " + run.run_id + ": cannot read its configuration: " + e.what());
  }
}

}  // namespace robozoo
