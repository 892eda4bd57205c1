#include "evolve/sim/episode/trajectory_sampler.hpp"

#include <stdexcept>

namespace robozoo {

std::vector<int32_t> trajectory_steps(int32_t steps_run, int every) {
  if (every < 1) throw std::invalid_argument("pose_every must be >= 1");
  std::vector<int32_t> steps;
  if (steps_run < 0) return steps;
  for (int64_t s = 0; s <= steps_run; s += every) steps.push_back(static_cast<int32_t>(s));
  if (steps_run % every != 0) steps.push_back(steps_run);
  return steps;
}

SimResult sample_trajectory(Simulation& sim, int every, const std::function<void(const SimState&)>& sample) {
  if (every < 1) throw std::invalid_argument("pose_every must be >= 1");
  sample(sim.state());  // step 0: the starting state
  while (sim.step())
    if (sim.state().step % every == 0) sample(sim.state());
  if (sim.state().step % every != 0) sample(sim.state());  // the last step, whatever `every`
  return sim.result();
}

}  // namespace robozoo
