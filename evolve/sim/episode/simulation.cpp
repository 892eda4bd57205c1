#include "evolve/sim/episode/simulation.hpp"

#include <cmath>
#include <ctime>
#include <stdexcept>
#include <string>

#include <ode/ode.h>

#include "evolve/sim/step/contacts.hpp"
#include "evolve/sim/step/ctrnn.hpp"
#include "evolve/sim/setup/params_check.hpp"
#include "evolve/core/cpu_time.hpp"
#include "evolve/sim/setup/robot_check.hpp"
#include "evolve/sim/episode/episode_rules.hpp"
#include "evolve/sim/step/sensors.hpp"
#include "evolve/sim/step/servo.hpp"
#include "evolve/sim/setup/world.hpp"

namespace robozoo {
namespace {

Eigen::Vector3d vec(const dReal* p) { return {p[0], p[1], p[2]}; }

}  // namespace

struct Simulation::Impl {
  const Robot robot;  // a copy: the world, the controller and the rules refer to it
  const SimParams p;
  OdeWorld world;
  ContactFinder finder;
  Ctrnn ctrnn;
  std::vector<double> limits;
  std::vector<int> joint_of_sphere;
  std::vector<Contact> contacts;
  std::vector<uint8_t> on_ground;
  std::vector<double> angles, prev_outputs, output_change;
  std::vector<Eigen::Vector3d> lin_vel, ang_vel;
  EpisodeRecord record;
  SimState state;
  double d_init = 0.0;
  unsigned long rand_seed;
  bool done = false;
  bool timing_on = false;
  Timing timing;

  Impl(const Robot& r, const SimParams& params)
      : robot((check_robot(r), r)),
        p(params),
        world(robot, params),
        finder(robot),
        ctrnn(robot),
        limits(motor_torque_limits(robot, params)),
        joint_of_sphere(robot.spheres.size(), -1),
        angles(robot.joints.size(), 0.0),
        lin_vel(robot.num_bodies, Eigen::Vector3d::Zero()),
        ang_vel(robot.num_bodies, Eigen::Vector3d::Zero()),
        record(static_cast<int>(robot.spheres.size()), robot.num_bodies),
        rand_seed(params.ode_seed) {
    for (size_t k = 0; k < robot.joints.size(); ++k) joint_of_sphere[robot.joints[k].sphere] = static_cast<int>(k);
    // dRandInt drives quickstep's constraint reordering; its seed is process-global,
    // so each simulation keeps its own and installs it around every step.
    // The motors' torque limits hold for the whole episode; only their speeds change.
    set_servo_torque_limits(world, limits);
    dRandSetSeed(rand_seed);
    // The initial state: contacts found (not yet joints) so touch sensors read true values.
    finder.find(world, p, contacts, state.sphere_touching, on_ground);
    contacts.clear();
    observe();
    d_init = distance_to_target();
    if (p.steps == 0) done = true;
  }

  double distance_to_target() const {
    return (world.center_of_mass() - Eigen::Vector3d(p.target_x, p.target_y, p.target_z)).norm();
  }

  // Reads poses, sphere centres, joint angles and sensors into the state.
  void observe() {
    const int nb = world.num_bodies();
    state.body_position.resize(nb);
    state.body_quaternion.resize(nb);
    for (int b = 0; b < nb; ++b) {
      state.body_position[b] = vec(dBodyGetPosition(world.body(b)));
      const dReal* q = dBodyGetQuaternion(world.body(b));
      state.body_quaternion[b] = {q[0], q[1], q[2], q[3]};
    }
    state.sphere_center.resize(world.num_spheres());
    for (int s = 0; s < world.num_spheres(); ++s) state.sphere_center[s] = world.sphere_center(s);
    for (int k = 0; k < world.num_joints(); ++k) angles[k] = dJointGetHingeAngle(world.hinge(k));
    state.neuron_output = ctrnn.outputs();
    read_sensors(robot, p, state.sphere_center, state.sphere_touching, angles, joint_of_sphere, state.time,
                 state.sensor_value);
  }

  bool step() {
    if (done) return false;
    const double t0 = timing_on ? thread_cpu_seconds() : 0.0;
    // Controller: sensors (read after the previous step) -> CTRNN -> servo commands.
    prev_outputs = ctrnn.outputs();
    ctrnn.step(state.sensor_value.data(), p.dt);
    apply_servos(world, robot, ctrnn.outputs(), angles, p);  // angles: read by observe() at this instant
    const double t1 = timing_on ? thread_cpu_seconds() : 0.0;
    // Physics.
    finder.find(world, p, contacts, state.sphere_touching, on_ground);
    add_contact_joints(world, p, contacts);
    dRandSetSeed(rand_seed);
    dWorldQuickStep(world.world(), p.dt);
    rand_seed = dRandGetSeed();
    dJointGroupEmpty(world.contact_group());
    const double t2 = timing_on ? thread_cpu_seconds() : 0.0;
    // Bookkeeping.
    ++state.step;
    state.time = state.step * p.dt;
    ++record.steps_run;
    bool finite = true;
    for (int b = 0; b < world.num_bodies(); ++b) {
      const Eigen::Vector3d v = vec(dBodyGetLinearVel(world.body(b)));
      const Eigen::Vector3d w = vec(dBodyGetAngularVel(world.body(b)));
      const double la = (v - lin_vel[b]).norm() / p.dt, aa = (w - ang_vel[b]).norm() / p.dt;
      if (!std::isfinite(la) || !std::isfinite(aa)) finite = false;
      record.max_linear_acceleration = std::max(record.max_linear_acceleration, la);
      record.max_angular_acceleration = std::max(record.max_angular_acceleration, aa);
      if (acceleration_fault(la, aa, p)) record.fault = true;
      lin_vel[b] = v;
      ang_vel[b] = w;
      record.angular_velocity_sum[b] += w;
    }
    for (size_t s = 0; s < on_ground.size(); ++s) record.ground_steps[s] += on_ground[s];
    if (!finite) record.fault = true;
    observe();
    output_change.resize(prev_outputs.size());
    for (size_t i = 0; i < prev_outputs.size(); ++i) output_change[i] = ctrnn.outputs()[i] - prev_outputs[i];
    record.rest_steps = at_rest(lin_vel, ang_vel, output_change, p) ? record.rest_steps + 1 : 0;
    if (record.fault) {
      done = true;
    } else if (record.rest_steps >= p.rest_steps && state.step < p.steps) {
      record.stopped_early = true;
      done = true;
    } else if (state.step >= p.steps) {
      done = true;
    }
    if (timing_on) {
      const double t3 = thread_cpu_seconds();
      timing.controller += t1 - t0;
      timing.physics += t2 - t1;
      timing.bookkeeping += t3 - t2;
      timing.contacts += static_cast<long long>(contacts.size());
    }
    return true;
  }
};

Simulation::Simulation(const Robot& robot, const SimParams& params) {
  check_sim_params(params);
  impl_ = std::make_unique<Impl>(robot, params);
}
Simulation::~Simulation() = default;

bool Simulation::step() { return impl_->step(); }
bool Simulation::done() const { return impl_->done; }
const SimState& Simulation::state() const { return impl_->state; }
void Simulation::set_body_velocity(int body, const Eigen::Vector3d& v, const Eigen::Vector3d& w) {
  if (impl_->state.step != 0) throw std::logic_error("Simulation::set_body_velocity: only before the first step");
  if (body < 0 || body >= impl_->world.num_bodies())
    throw std::invalid_argument("Simulation::set_body_velocity: no body " + std::to_string(body));
  dBodySetLinearVel(impl_->world.body(body), v.x(), v.y(), v.z());
  dBodySetAngularVel(impl_->world.body(body), w.x(), w.y(), w.z());
  impl_->lin_vel[body] = v;  // accelerations are measured from the velocities set here
  impl_->ang_vel[body] = w;
}
SimResult Simulation::result() const {
  return apply_rules(impl_->record, impl_->d_init, impl_->distance_to_target(), impl_->p);
}
Simulation::Timing Simulation::timing() const { return impl_->timing; }
void Simulation::enable_timing(bool on) { impl_->timing_on = on; }

SimResult simulate(const Robot& robot, const SimParams& params) {
  Simulation sim(robot, params);
  while (sim.step()) {
  }
  return sim.result();
}

}  // namespace robozoo
