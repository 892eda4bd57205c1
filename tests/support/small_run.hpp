#pragma once
// Test support: the small run many tests evolve in-process (seed 7, 24 robots,
// 400 steps): small enough for a second, big enough that champions reach the
// simulator, so its log holds trajectories.
#include <string>

#include "evolve/config/run_config.hpp"
#include "evolve/run/evaluator.hpp"
#include "evolve/run/evolution.hpp"

namespace robozoo::testing {

inline RunConfig small_run_config(int generations = 4) {
  RunConfig c;
  c.seed = 7;
  c.neat.population = 24;
  c.generations = generations;
  c.eval.sim.steps = 400;
  // M1 and M2's bias input: at the default 0.3 a feed-forward run grows no robot beyond the
  // root before mutation (docs/method.md section 2.1); these runs must reach the simulator.
  c.eval.growth.bias_input = 1.0;
  return c;
}

/// Evolves the small run (recurrent unless told) in-process into the log at `log_path`, as run `run_id`.
inline void evolve_small_run(const std::string& log_path, const std::string& run_id, int generations, int64_t seed = 7,
                             Regime regime = Regime::Recurrent) {
  RunConfig c = small_run_config(generations);
  c.seed = seed;
  c.regime = regime;
  InProcessEvaluator evaluator(c.eval);
  EvolveOptions o;
  o.log_path = log_path;
  o.run_id = run_id;
  Evolution evo(c, o, evaluator);
  evo.run({});
}

}  // namespace robozoo::testing
