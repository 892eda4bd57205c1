#pragma once
// ODE simulation of a grown robot (docs/method.md section 2 and 4). The Robot is a
// constant model; a Simulation holds the changing state. One Simulation owns one
// ODE world; never step two worlds from two threads of one process (ODE's
// dRandInt seed is process-global).
#include <array>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "evolve/growth/robot.hpp"
#include "evolve/sim/episode/outcome.hpp"
#include "evolve/sim/params.hpp"

namespace robozoo {

/// Result of a whole episode: what the fitness's d term and outcome come from.
struct SimResult {
  Outcome outcome = Outcome::Completed;
  int steps_run = 0;                            ///< steps actually simulated (count)
  bool stopped_early = false;                   ///< every body came to rest before the last step
  double d_init = 0.0;                          ///< initial COM distance to the target (m)
  double d_final = 0.0;                         ///< final COM distance, = d_init when invalidated (m)
  double d = 0.0;                               ///< d_init - d_final, 0 when invalidated (m)
  double d_raw = 0.0;                           ///< d_init - (actual final distance), before the rules (m)
  std::vector<double> ground_contact_fraction;  ///< per sphere, steps touching ground / steps_run
  std::vector<double> mean_angular_speed;       ///< per body, |time-averaged angular velocity| (rad/s)
  double max_linear_acceleration = 0.0;         ///< largest seen (m/s^2)
  double max_angular_acceleration = 0.0;        ///< largest seen (rad/s^2)
};

/// State observable after any step (for poses, replay and rendering).
struct SimState {
  int step = 0;                                  ///< steps taken so far
  double time = 0.0;                             ///< simulated time (s)
  std::vector<Eigen::Vector3d> body_position;    ///< body origin = its centre of mass (m)
  std::vector<Eigen::Vector4d> body_quaternion;  ///< (w, x, y, z)
  std::vector<Eigen::Vector3d> sphere_center;    ///< world centre of every sphere (m)
  std::vector<double> neuron_output;             ///< CTRNN outputs
  std::vector<double> sensor_value;              ///< robot.sensors order
  std::vector<uint8_t> sphere_touching;          ///< touch contact this step, per sphere
};

class Simulation {
 public:
  /// Checks `robot` (check_robot; std::invalid_argument on a bad model or bad
  /// params), keeps a copy of it, builds the ODE world and calls
  /// dRandSetSeed(params.ode_seed). Sensors are read once so state() is valid
  /// before the first step.
  Simulation(const Robot& robot, const SimParams& params);
  ~Simulation();
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  /// One physics step: sensors -> CTRNN -> servos -> collide -> quickstep ->
  /// bookkeeping. Returns true when it took a step; once the episode is over
  /// (all steps run, early stop, or a fault) calls do nothing and return false,
  /// so `while (sim.step()) use(sim.state());` sees every state, the last included.
  bool step();
  bool done() const;
  const SimState& state() const;
  /// Gives body b an initial linear (m/s) and angular (rad/s) velocity. Only
  /// before the first step (throws std::logic_error after); for tests and
  /// perturbation experiments. Evaluations never call it.
  void set_body_velocity(int body, const Eigen::Vector3d& linear, const Eigen::Vector3d& angular);
  /// The episode's result (rules applied; precedence in evolve/sim/episode/episode_rules.hpp);
  /// valid once done(), partial before (the rules judge the steps run so far).
  SimResult result() const;

  /// Per-stage CPU time of the calling thread in seconds accumulated so far (for
  /// the benchmark; the machine may be shared, and wall time would count others).
  struct Timing {
    double controller = 0, physics = 0, bookkeeping = 0;
    long long contacts = 0;  ///< contact joints handed to the solver, summed over the timed steps
  };
  Timing timing() const;
  void enable_timing(bool on);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Runs a whole episode.
SimResult simulate(const Robot& robot, const SimParams& params);

/// Steps the same bodies and joints with no controller, sensors, servo or
/// bookkeeping (joint motors held at zero speed with the same force limit), for
/// `steps` steps: the engine's limit, used as the benchmark's baseline. Returns
/// the contact joints handed to the solver, summed over the steps.
long long simulate_bare(const Robot& robot, const SimParams& params, int steps);

/// Stable 64-bit hash of all body positions and quaternions (exact bits).
uint64_t pose_hash(const SimState& s);

}  // namespace robozoo
