#pragma once
// A robot's trajectory as every program samples it: the state at step 0, at
// every k-th step, and at the last step simulated (whatever k). robozoo-evolve
// logs a champion's poses this way, robozoo-replay re-creates and publishes
// them, render and view re-simulate a genome's motion with it.
#include <cstdint>
#include <functional>
#include <vector>

#include "evolve/sim/episode/simulation.hpp"

namespace robozoo {

/// The steps at which a trajectory of `steps_run` steps is sampled, in order:
/// 0, k, 2k, ... and steps_run when it is not a multiple of k (k = every >= 1).
/// Throws std::invalid_argument when every < 1.
std::vector<int32_t> trajectory_steps(int32_t steps_run, int every);

/// Runs `sim` to the end of its episode and calls `sample` with its state at
/// each step of trajectory_steps(steps run, every), in order, as it gets there;
/// returns the simulation's result. Throws std::invalid_argument when every < 1
/// (before stepping).
SimResult sample_trajectory(Simulation& sim, int every, const std::function<void(const SimState&)>& sample);

}  // namespace robozoo
