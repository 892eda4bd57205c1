// The r term of the fitness (paper 2.4), declared in growth.hpp.
#include <algorithm>

#include "evolve/growth/growth.hpp"

namespace robozoo {

void score_r_term(Robot& robot) {
  const bool any_sensor = !robot.sensors.empty();
  const bool any_joint = !robot.joints.empty();
  const bool any_neuron_link = robot.w_neuron_neuron.size() > 0 && (robot.w_neuron_neuron.array() != 0.0).any();
  const bool any_sensor_link = robot.w_sensor_neuron.size() > 0 && (robot.w_sensor_neuron.array() != 0.0).any();
  const bool distance = std::any_of(robot.sensors.begin(), robot.sensors.end(),
                                    [](const Sensor& s) { return s.type == SensorType::Distance; });
  double r = 1.0;
  r += any_sensor;
  r += any_joint;
  r += any_neuron_link;
  r += any_sensor_link;
  robot.simulate = any_sensor && any_joint && any_neuron_link && any_sensor_link && distance;
  if (robot.simulate) r += 10.0;
  robot.r_term = r;
}

}  // namespace robozoo
