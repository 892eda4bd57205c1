#include "render/video_subject.hpp"

#include <stdexcept>

#include <nlohmann/json.hpp>

#include "evolve/config/run_config.hpp"
#include "render/robot_card.hpp"
#include "render/selection.hpp"
#include "render/trajectory.hpp"

namespace robozoo::render {

Eigen::Vector3d run_target(const run_t& run) {
  try {
    const RunConfig c = config_from_json(nlohmann::json::parse(run.config_json));
    return {c.eval.sim.target_x, c.eval.sim.target_y, c.eval.sim.target_z};
  } catch (const std::exception& e) {
    throw std::invalid_argument("run " + run.run_id + ": cannot read its configuration: " + e.what());
  }
}

VideoSubject make_video_subject(const RunRecord& run, const GenomeRecord& genome, bool resimulate) {
  VideoSubject s;
  s.card = make_card(run, genome);
  s.target = run_target(run.run);
  const size_t n = s.card.shape.size();
  if (resimulate) {
    s.trajectory = simulate_trajectory(run.run, genome.genome, genome.morphology);
    return s;
  }
  if (!genome.poses.empty()) {
    s.trajectory = trajectory_from_poses(genome.poses, n);
    return s;
  }
  const uint64_t genes = gene_hash(genome.genome);
  for (const auto& other : run.genomes)
    if (other.get() != &genome && !other->poses.empty() && other->has_morphology &&
        other->morphology.num_spheres == genome.morphology.num_spheres && gene_hash(other->genome) == genes) {
      s.trajectory = trajectory_from_poses(other->poses, n);
      return s;
    }
  s.trajectory = simulate_trajectory(run.run, genome.genome, genome.morphology);
  return s;
}

}  // namespace robozoo::render
