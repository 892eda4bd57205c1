#pragma once
// The robot's controller: a CTRNN integrated by explicit Euler at the physics step.
//   tau_i dy_i/dt = -y_i + sum_j w_ji sigma(y_j + omega_j) + sum_k w_ki s_k
// sigma = tanh, so neuron outputs lie in (-1, 1) and map to joint targets.
#include <vector>

#include "evolve/growth/robot.hpp"

namespace robozoo {

class Ctrnn {
 public:
  explicit Ctrnn(const Robot& robot);
  /// Sets every state y to 0.
  void reset();
  /// One explicit Euler step of dt seconds with the given sensor values (robot.sensors order).
  void step(const double* sensor_values, double dt);
  /// sigma(y_i + omega_i) for every neuron.
  const std::vector<double>& outputs() const { return out_; }
  const std::vector<double>& state() const { return y_; }
  int size() const { return static_cast<int>(y_.size()); }

 private:
  const Robot* robot_;
  std::vector<double> y_, out_, dy_;
};

}  // namespace robozoo
