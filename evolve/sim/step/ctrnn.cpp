#include "evolve/sim/step/ctrnn.hpp"

#include "evolve/math/tanh.hpp"

#include <stdexcept>
#include <string>

namespace robozoo {

Ctrnn::Ctrnn(const Robot& robot) : robot_(&robot) {
  const int n = static_cast<int>(robot.neurons.size());
  const int k = static_cast<int>(robot.sensors.size());
  if (robot.w_neuron_neuron.rows() != n || robot.w_neuron_neuron.cols() != n)
    throw std::invalid_argument("Ctrnn: w_neuron_neuron must be " + std::to_string(n) + "x" + std::to_string(n));
  if (robot.w_sensor_neuron.rows() != k || robot.w_sensor_neuron.cols() != n)
    throw std::invalid_argument("Ctrnn: w_sensor_neuron must be " + std::to_string(k) + "x" + std::to_string(n));
  for (int i = 0; i < n; ++i)
    if (!(robot.neurons[i].tau > 0))
      throw std::invalid_argument("Ctrnn: neuron " + std::to_string(i) + " has tau <= 0");
  y_.assign(n, 0.0);
  out_.assign(n, 0.0);
  dy_.assign(n, 0.0);
  reset();
}

void Ctrnn::reset() {
  for (size_t i = 0; i < y_.size(); ++i) {
    y_[i] = 0.0;
    out_[i] = math::tanh(robot_->neurons[i].omega);
  }
}

void Ctrnn::step(const double* sensor_values, double dt) {
  const Robot& r = *robot_;
  const int n = size();
  const int k = static_cast<int>(r.sensors.size());
  // Right-hand sides from the current outputs (all neurons read the same instant).
  for (int i = 0; i < n; ++i) {
    double in = -y_[i];
    for (int j = 0; j < n; ++j) in += r.w_neuron_neuron(j, i) * out_[j];
    for (int s = 0; s < k; ++s) in += r.w_sensor_neuron(s, i) * sensor_values[s];
    dy_[i] = in / r.neurons[i].tau;
  }
  for (int i = 0; i < n; ++i) {
    y_[i] += dt * dy_[i];
    out_[i] = math::tanh(y_[i] + r.neurons[i].omega);
  }
}

}  // namespace robozoo
