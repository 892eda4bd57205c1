#pragma once
// Physics, controller, sensor and fitness-rule parameters (paper 2.4, docs/method.md
// section 2). Defaults keep random robots of 1-50 spheres stable; each default
// that was tuned says here how (measured with tools/measure/robozoo-simstats on
// evolve/sim/robots/random_robot robots; details in evolve/sim/README.md).
#include <cstdint>

namespace robozoo {

struct SimParams {
  // Episode
  int steps = 2500;               ///< physics steps per evaluation (count)
  double dt = 0.01;               ///< physics step (s)
  double gravity = 9.81;          ///< (m/s^2), along -z
  uint32_t ode_seed = 0;          ///< dRandSetSeed value before the first step
  int quickstep_iterations = 20;  ///< dWorldSetQuickStepNumIterations (count)
  // Contacts and joints
  double erp = 0.2;                      ///< world error reduction parameter (joints and stops)
  double cfm = 1e-5;                     ///< world constraint force mixing (joints and stops)
  double contact_erp = 0.2;              ///< contact ERP (soft contacts)
  double contact_cfm = 1e-4;             ///< contact CFM (soft contacts)
  double friction = 1.0;                 ///< Coulomb friction coefficient mu (dContactApprox1:
                                         ///< the friction bound is mu times the normal force)
  int max_contacts = 4;                  ///< contact points per geom pair (count)
  double max_correcting_velocity = 1.0;  ///< dWorldSetContactMaxCorrectingVel: cap on the speed at
                                         ///< which contacts push interpenetrating parts apart (m/s)
  // Motors: velocity servo towards the CTRNN's target angle
  double servo_gain = 10.0;       ///< target joint speed per rad of angle error (1/s)
  double servo_max_speed = 10.0;  ///< cap on the commanded joint speed (rad/s)
  double motor_strength = 10.0;   ///< hinge torque limit in units of the largest gravity torque
                                  ///< the lighter of the two hinged bodies exerts about the
                                  ///< anchor (dimensionless): limit = motor_strength * gravity *
                                  ///< min over the two bodies of sum(mass * distance to anchor).
                                  ///< Faults: 0.3-0.4 % of random and of grown robots at 10, 5 % of
                                  ///< grown ones at 20, 12 % at 30, half of all robots at 100.
  // Target and sensors
  double target_x = 50.0;                ///< target position (m): far enough that no robot reaches it in 25 s
  double target_y = 0.0;                 ///< (m)
  double target_z = 0.0;                 ///< (m)
  double distance_sensor_range = 100.0;  ///< distance at which the sensor reads 0 (m)
  double time_sensor_frequency = 1.0;    ///< f of sin(2 pi f t) (Hz)
  // Early stop: every body slower than both speeds and every neuron output changing
  // slower than rest_output_rate, for rest_steps consecutive steps.
  double rest_linear_speed = 1e-3;   ///< a body is at rest below this speed (m/s)
  double rest_angular_speed = 1e-3;  ///< ... and below this angular speed (rad/s)
  double rest_output_rate = 1e-3;    ///< ... and the controller below this |d output/dt| (1/s)
  int rest_steps = 50;               ///< consecutive steps at rest that end the run (count)
  // Faults: per-body acceleration from consecutive velocities, (v_t - v_{t-1}) / dt.
  // Chosen on random and on grown robots (evolve/sim/README.md): those that stay
  // sane peak at 1,330-1,630 m/s^2 and 15,700-19,400 rad/s^2 (95 % under 570 and
  // 11,100), while every robot that exploded with motor_strength 100 or 1,000
  // passed both thresholds.
  double max_linear_acceleration = 2000.0;    ///< fault above this (m/s^2)
  double max_angular_acceleration = 20000.0;  ///< fault above this (rad/s^2)
  // Rolling rules (paper 2.4)
  bool rolling_contact_rule = true;        ///< rule (i): some sphere in ground contact > fraction of steps
  double rolling_contact_fraction = 0.95;  ///< rule (i)'s fraction of the steps run (dimensionless)
  bool rolling_spin_rule = true;           ///< rule (ii): |time-averaged angular velocity| of a body > threshold
  /// Rule (ii)'s threshold (rad/s), from the worst body's time-averaged angular
  /// speed of robots that moved without a fault: random robots (661 movers of
  /// 1,000): median 0.07, 95th percentile 0.40, 99th 0.71 rad/s; robots grown
  /// from random CPPNs (308 movers): median 0.08, 95th 0.94, 99th 1.32. 1.0 passes
  /// 99.8 % and 95.5 % of them; a body that fails it turned more than 25 rad
  /// (4 turns) one way in the 25 s episode: it rolled.
  double rolling_spin_threshold = 1.0;
};

}  // namespace robozoo
