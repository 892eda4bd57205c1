#include "evolve/run/trajectory.hpp"

#include <stdexcept>

#include "evolve/messages/build.hpp"

namespace robozoo {

uint64_t trajectory_key(const Genome& champion) {
  Genome g = champion;
  g.id = 0;
  for (auto& l : g.links) l.born = 0;
  return genome_hash(g);
}

PoseStream simulate_pose_stream(const Robot& robot, const SimParams& params, int pose_every, const std::string& run_id,
                                int32_t generation, int64_t genome_id) {
  if (pose_every < 1) throw std::invalid_argument("pose_every must be >= 1");
  Simulation sim(robot, params);
  PoseStream t;
  t.result = sample_trajectory(sim, pose_every, [&](const SimState& state) {
    t.poses.push_back(make_pose_message(run_id, generation, genome_id, state, 0));
  });
  return t;
}

}  // namespace robozoo
