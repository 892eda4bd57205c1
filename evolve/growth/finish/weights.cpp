#include "evolve/growth/finish/weights.hpp"

#include <cmath>
#include <stdexcept>

#include "evolve/growth/growth.hpp"

namespace robozoo {

double expressed_weight(double output_w, const GrowthParams& params) {
  const double t = params.weight_threshold;
  if (!(std::abs(output_w) > t)) return 0.0;
  if (params.weight_mapping == WeightMapping::Proportional) return output_w * params.weight_max;
  // HyperNEAT: (w - T) / (1 - T) * w_max above the threshold, (w + T) / (1 - T) * w_max below -T.
  const double beyond = output_w > 0 ? output_w - t : output_w + t;
  return beyond / (1.0 - t) * params.weight_max;
}

void set_ctrnn_weights(Robot& robot, CppnProbe& probe, const GrowthParams& params) {
  const auto ns = static_cast<Eigen::Index>(robot.sensors.size());
  const auto nn = static_cast<Eigen::Index>(robot.neurons.size());
  robot.w_sensor_neuron = Eigen::MatrixXd::Zero(ns, nn);
  robot.w_neuron_neuron = Eigen::MatrixXd::Zero(nn, nn);
  auto center = [&](int sphere) -> const Eigen::Vector3d& {
    if (sphere < 0 || sphere >= static_cast<int>(robot.spheres.size()))
      throw std::logic_error("set_ctrnn_weights: sensor or neuron on a missing sphere");
    return robot.spheres[sphere].center;
  };
  // Every query of the robot in one batch: sensor k -> neuron i, then the pairs
  // j <= i of neurons.
  const Eigen::Index pairs = nn * (nn + 1) / 2;
  probe.begin(static_cast<int>(ns * nn + pairs));
  int q = 0;
  for (Eigen::Index k = 0; k < ns; ++k) {
    const Sensor& s = robot.sensors[k];
    const Eigen::Vector3d& a = center(s.sphere);
    for (Eigen::Index i = 0; i < nn; ++i) probe.set(q++, (a + center(robot.neurons[i].sphere)) / 2.0, 0.0, &s.type);
  }
  for (Eigen::Index j = 0; j < nn; ++j) {
    const Eigen::Vector3d& a = center(robot.neurons[j].sphere);
    for (Eigen::Index i = j; i < nn; ++i) probe.set(q++, (a + center(robot.neurons[i].sphere)) / 2.0, 0.0);
  }
  probe.run();
  q = 0;
  for (Eigen::Index k = 0; k < ns; ++k)
    for (Eigen::Index i = 0; i < nn; ++i)
      robot.w_sensor_neuron(k, i) = expressed_weight(probe.output(q++, kOutWeight), params);
  for (Eigen::Index j = 0; j < nn; ++j)
    for (Eigen::Index i = j; i < nn; ++i)
      robot.w_neuron_neuron(j, i) = robot.w_neuron_neuron(i, j) =
          expressed_weight(probe.output(q++, kOutWeight), params);
}

}  // namespace robozoo
