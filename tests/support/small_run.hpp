#pragma once
// Test support: the small run many tests evolve in-process (seed 7, 24 robots,
// 400 steps): small enough for a second, big enough that champions reach the
// simulator, so its log holds trajectories.
#include "evolve/config/run_config.hpp"

namespace robozoo::testing {

inline RunConfig small_run_config(int generations = 4) {
  RunConfig c;
  c.seed = 7;
  c.neat.population = 24;
  c.generations = generations;
  c.eval.sim.steps = 400;
  return c;
}

}  // namespace robozoo::testing
