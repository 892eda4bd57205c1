#include "evolve/fitness/evaluate.hpp"

#include <algorithm>

#include "evolve/cppn/network.hpp"
#include "evolve/growth/growth.hpp"

namespace robozoo {

Robot grow_genome(const Genome& genome, const EvalParams& params) {
  Network cppn(genome, robot_layout(), params.cppn_updates);
  return grow(cppn, params.growth);
}

Evaluation evaluate(const Genome& genome, const EvalParams& params) {
  const Robot robot = grow_genome(genome, params);
  Evaluation e;
  e.r = robot.r_term;
  e.num_spheres = static_cast<int>(robot.spheres.size());
  e.num_bodies = robot.num_bodies;
  e.num_joints = static_cast<int>(robot.joints.size());
  e.num_sensors = static_cast<int>(robot.sensors.size());
  if (robot.simulate) {
    e.sim = simulate(robot, params.sim);
    e.d = e.sim.d;
    e.outcome = e.sim.outcome;
  }
  // f = r + d (paper 2.4). d may be negative (the robot moved away from the
  // target); f is clamped at 0 because NEAT's fitness sharing and selection need
  // f >= 0. A simulated robot has r >= 15, so the clamp acts only if a valid run
  // (no fault, no rolling) ends over 15 m further from the target than it
  // started, which a robot within a 4 m square moving for 25 s does not do.
  e.fitness = std::max(0.0, e.r + e.d);
  return e;
}

}  // namespace robozoo
