#pragma once
// Physics, controller, sensor and fitness-rule parameters (paper 2.4, DESIGN.md
// section 2). Defaults keep random robots of 1-50 spheres stable; each default
// that was tuned says here how (measured with tools/robozoo-simstats on
// evolve/sim/random_robot robots; details in evolve/sim/README.md).
#include <cstdint>

namespace robozoo {

struct SimParams {
  // Episode
  int steps = 2500;                  ///< physics steps per evaluation (count)
  double dt = 0.01;                  ///< physics step (s)
  double gravity = 9.81;             ///< (m/s^2), along -z
  uint32_t ode_seed = 0;             ///< dRandSetSeed value before the first step
  int quickstep_iterations = 20;     ///< dWorldSetQuickStepNumIterations (count)
  // Contacts and joints
  double erp = 0.2;                  ///< world error reduction parameter (joints and stops)
  double cfm = 1e-5;                 ///< world constraint force mixing (joints and stops)
  double contact_erp = 0.2;          ///< contact ERP (soft contacts)
  double contact_cfm = 1e-4;         ///< contact CFM (soft contacts)
  double friction = 1.0;             ///< Coulomb friction coefficient mu (dContactApprox1:
                                     ///< the friction bound is mu times the normal force)
  int max_contacts = 4;              ///< contact points per geom pair (count)
  double max_correcting_velocity = 1.0;  ///< dWorldSetContactMaxCorrectingVel: cap on the speed at
                                         ///< which contacts push interpenetrating parts apart (m/s)
  // Motors: velocity servo towards the CTRNN's target angle
  double servo_gain = 10.0;          ///< target joint speed per rad of angle error (1/s)
  double servo_max_speed = 10.0;     ///< cap on the commanded joint speed (rad/s)
  double motor_strength = 10.0;      ///< hinge torque limit in units of the torque that holds the
                                     ///< hinge's lighter side level against gravity
                                     ///< (dimensionless): limit = motor_strength * gravity *
                                     ///< min over the two sides of sum(mass * distance to anchor).
                                     ///< Random robots: 0-3 % faults for 5-30; at 100, 9 % of robots
                                     ///< explode (|d| > 5 m, bodies thrown > 3 m) at 100.
                                     ///< 10 leaves a margin of ~10x below that.
  // Target and sensors
  double target_x = 10.0;            ///< target position (m)
  double target_y = 0.0;             ///< (m)
  double target_z = 0.0;             ///< (m)
  double distance_sensor_range = 20.0;  ///< distance at which the sensor reads 0 (m)
  double time_sensor_frequency = 1.0;   ///< f of sin(2 pi f t) (Hz)
  // Early stop: every body slower than both speeds and every neuron output changing
  // slower than rest_output_rate, for rest_steps consecutive steps.
  double rest_linear_speed = 1e-3;   ///< a body is at rest below this speed (m/s)
  double rest_angular_speed = 1e-3;  ///< ... and below this angular speed (rad/s)
  double rest_output_rate = 1e-3;    ///< ... and the controller below this |d output/dt| (1/s)
  int rest_steps = 50;               ///< consecutive steps at rest that end the run (count)
  // Faults: per-body acceleration from consecutive velocities, (v_t - v_{t-1}) / dt.
  // Chosen on random robots: at the default physics the largest accelerations of
  // robots that stay sane reach ~1,000 m/s^2 and ~20,000 rad/s^2 (a small sphere
  // landing after a fall; 95 % of robots stay under 470 and 6,700), while every
  // robot that exploded with motor_strength 100 passed both thresholds.
  double max_linear_acceleration = 2000.0;   ///< fault above this (m/s^2)
  double max_angular_acceleration = 20000.0;  ///< fault above this (rad/s^2)
  // Rolling rules (paper 2.4)
  bool rolling_contact_rule = true;  ///< rule (i): some sphere in ground contact > fraction of steps
  double rolling_contact_fraction = 0.95;  ///< rule (i)'s fraction of the steps run (dimensionless)
  bool rolling_spin_rule = true;     ///< rule (ii): |time-averaged angular velocity| of a body > threshold
  /// Rule (ii)'s threshold (rad/s). Chosen from 683 random robots (1,000 drawn,
  /// 1-50 spheres) that moved without a fault: their worst body's time-averaged
  /// angular speed has median 0.07, 95th percentile 0.42, 99th 0.77 and maximum
  /// 1.15 rad/s. 1.0 sits above 99.7 % of them, so unpurposeful flailing and
  /// settling pass, while a body failing it turns over more than 25 rad (4 turns)
  /// one way in the 25 s episode: rolling (0.5 m/s on a sphere of radius 0.5).
  double rolling_spin_threshold = 1.0;
};

}  // namespace robozoo
