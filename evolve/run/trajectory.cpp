#include "evolve/run/trajectory.hpp"

#include <stdexcept>

#include "evolve/messages/build.hpp"

namespace robozoo {

std::vector<int32_t> trajectory_steps(int32_t steps_run, int pose_every) {
  if (pose_every < 1) throw std::invalid_argument("pose_every must be >= 1");
  std::vector<int32_t> steps;
  if (steps_run < 0) return steps;
  for (int64_t s = 0; s <= steps_run; s += pose_every) steps.push_back(static_cast<int32_t>(s));
  if (steps_run % pose_every != 0) steps.push_back(steps_run);
  return steps;
}

uint64_t trajectory_key(const Genome& champion) {
  Genome g = champion;
  g.id = 0;
  for (auto& l : g.links) l.born = 0;
  return genome_hash(g);
}

Trajectory simulate_trajectory(const Robot& robot, const SimParams& params, int pose_every, const std::string& run_id,
                               int32_t generation, int64_t genome_id) {
  if (pose_every < 1) throw std::invalid_argument("pose_every must be >= 1");
  Simulation sim(robot, params);
  Trajectory t;
  auto pose = [&] { t.poses.push_back(make_pose_message(run_id, generation, genome_id, sim.state(), 0)); };
  pose();  // step 0: the starting pose
  while (sim.step()) {
    if (sim.state().step % pose_every == 0) pose();
  }
  if (sim.state().step % pose_every != 0) pose();  // the final pose, whatever pose_every
  t.result = sim.result();
  return t;
}

}  // namespace robozoo
