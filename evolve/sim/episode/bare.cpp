// simulate_bare(): the engine's limit for the benchmark. The same world,
// contacts, ground and quickstep as Simulation, with the motors held at zero
// speed under the same torque limits, and nothing else per step.
#include <ode/ode.h>

#include "evolve/sim/step/contacts.hpp"
#include "evolve/sim/setup/params_check.hpp"
#include "evolve/sim/setup/robot_check.hpp"
#include "evolve/sim/step/servo.hpp"
#include "evolve/sim/episode/simulation.hpp"
#include "evolve/sim/setup/world.hpp"

namespace robozoo {

long long simulate_bare(const Robot& robot, const SimParams& params, int steps) {
  check_robot(robot);
  check_sim_params(params);
  OdeWorld world(robot, params);
  const ContactFinder finder(robot);
  const std::vector<double> limits = motor_torque_limits(robot, params);
  for (int k = 0; k < world.num_joints(); ++k) {
    dJointSetHingeParam(world.hinge(k), dParamVel, 0);
    dJointSetHingeParam(world.hinge(k), dParamFMax, limits[k]);
  }
  std::vector<Contact> contacts;
  std::vector<uint8_t> touching, on_ground;
  long long total = 0;
  dRandSetSeed(params.ode_seed);
  for (int i = 0; i < steps; ++i) {
    finder.find(world, params, contacts, touching, on_ground);
    total += static_cast<long long>(contacts.size());
    add_contact_joints(world, params, contacts);
    dWorldQuickStep(world.world(), params.dt);
    dJointGroupEmpty(world.contact_group());
  }
  return total;
}

}  // namespace robozoo
