#pragma once
// One evaluation = a pure function of (genome, configuration): decode the CPPN,
// grow the robot, score r, simulate when r earns it, f = r + d (paper 2.4).
#include "evolve/cppn/genome.hpp"
#include "evolve/growth/params.hpp"
#include "evolve/growth/robot.hpp"
#include "evolve/sim/params.hpp"
#include "evolve/sim/episode/simulation.hpp"

namespace robozoo {

struct EvalParams {
  GrowthParams growth;
  SimParams sim;
  int cppn_updates = 10;  ///< synchronous CPPN updates per query (count)
};

struct Evaluation {
  double fitness = 0.0;  ///< r + d
  double r = 0.0;
  double d = 0.0;
  Outcome outcome = Outcome::NotSimulated;
  int num_spheres = 0, num_bodies = 0, num_joints = 0, num_sensors = 0;
  SimResult sim;  ///< empty when not simulated
};

Evaluation evaluate(const Genome& genome, const EvalParams& params);
/// Decodes and grows only.
Robot grow_genome(const Genome& genome, const EvalParams& params);

}  // namespace robozoo
