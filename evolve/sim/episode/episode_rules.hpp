#pragma once
// The fitness's d-term rules (paper 2.4, docs/method.md section 2): what an episode
// records while it runs, the per-step tests (acceleration fault, rest), and the
// end-of-episode decision.
//
// Precedence (one outcome per episode; the first that holds wins):
//   1. AccelFault     the run stopped on an acceleration over threshold (or a
//                     non-finite state): d = 0.
//   2. RollingContact rule (i), when enabled: some sphere had a ground contact in
//                     more than rolling_contact_fraction of the steps run: d = 0.
//   3. RollingSpin    rule (ii), when enabled: some body's time-averaged angular
//                     velocity vector has magnitude > rolling_spin_threshold: d = 0.
//   4. StoppedEarly   every body at rest (see at_rest): d = d_init - d_final at the stop.
//   5. Completed      all steps run: d = d_init - d_final.
// A fault cuts the episode short, so its rule data cover only the steps run and
// are not judged. The rolling rules judge early-stopped runs over the steps
// run, like completed ones (SimResult::stopped_early keeps the stop visible).
#include <vector>

#include <Eigen/Core>

#include "evolve/sim/params.hpp"
#include "evolve/sim/episode/simulation.hpp"

namespace robozoo {

struct EpisodeRecord {
  int steps_run = 0;                                  ///< steps simulated (count)
  std::vector<int> ground_steps;                      ///< per sphere: steps with a ground contact
  std::vector<Eigen::Vector3d> angular_velocity_sum;  ///< per body: sum over steps (rad/s)
  double max_linear_acceleration = 0.0;               ///< (m/s^2)
  double max_angular_acceleration = 0.0;              ///< (rad/s^2)
  int rest_steps = 0;                                 ///< consecutive steps at rest so far
  bool fault = false;
  bool stopped_early = false;

  EpisodeRecord(int num_spheres, int num_bodies)
      : ground_steps(num_spheres, 0), angular_velocity_sum(num_bodies, Eigen::Vector3d::Zero()) {}
};

/// True when either acceleration passes its threshold or is not finite.
bool acceleration_fault(double linear_acceleration, double angular_acceleration, const SimParams& params);

/// True when every body's speeds are below the rest speeds and every neuron
/// output changed by less than rest_output_rate * dt in the last step.
bool at_rest(const std::vector<Eigen::Vector3d>& linear_velocity, const std::vector<Eigen::Vector3d>& angular_velocity,
             const std::vector<double>& output_change, const SimParams& params);

/// The episode's result from its record (precedence above). d_final is the
/// robot's distance to the target at the last step run.
SimResult apply_rules(const EpisodeRecord& record, double d_init, double d_final, const SimParams& params);

}  // namespace robozoo
