#include "study/analysis/measure/initial_robots.hpp"

#include "evolve/fitness/evaluate.hpp"
#include "evolve/neat/start/initial_genome.hpp"

namespace robozoo {

InitialRobotShares initial_robot_shares(const RunConfig& config, int64_t genomes, uint64_t seed) {
  InitialRobotShares s;
  Rng rng(seed);
  const GenomeLayout layout = robot_layout();
  double spheres = 0, links = 0;
  for (int64_t i = 0; i < genomes; ++i) {
    const Genome g = initial_genome(layout, i, config.neat, config.regime, rng);
    const Robot r = grow_genome(g, config.eval);
    bool distance = false;
    for (const auto& sensor : r.sensors) distance |= sensor.type == SensorType::Distance;
    ++s.genomes;
    s.beyond_root += r.spheres.size() > 1;
    s.with_joint += !r.joints.empty();
    s.joint_and_distance += !r.joints.empty() && distance;
    s.simulated += r.simulate;
    spheres += static_cast<double>(r.spheres.size());
    links += static_cast<double>(g.links.size());
  }
  if (s.genomes > 0) {
    s.mean_spheres = spheres / static_cast<double>(s.genomes);
    s.mean_links = links / static_cast<double>(s.genomes);
  }
  return s;
}

}  // namespace robozoo
