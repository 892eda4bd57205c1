#pragma once
// Querying the robot CPPN at a point (docs/method.md section 2: inputs x, y, z,
// r_parent, bias, four sensor one-hots; eleven outputs). Allocation-free.
#include <array>

#include <Eigen/Core>

#include "evolve/cppn/network.hpp"
#include "evolve/growth/robot.hpp"

namespace robozoo {

constexpr int kCppnInputs = 9;
constexpr int kCppnOutputs = 11;
using CppnOutputs = std::array<double, kCppnOutputs>;

class CppnProbe {
 public:
  /// `cppn` must have the robot layout (9 inputs, 11 outputs), else
  /// std::invalid_argument. The probe keeps a reference: the network must outlive it.
  CppnProbe(Network& cppn, double bias_input);

  /// Queries at point p with the given r_parent input; `one_hot` sets that
  /// sensor type's input to 1 (weight queries from a sensor), nullptr for none.
  /// A non-finite output (possible only with unbounded activations such as
  /// Linear in a recurrent loop) is read as 0, "no signal", so that every
  /// threshold and mapping downstream sees a number.
  void query(const Eigen::Vector3d& p, double r_parent, const SensorType* one_hot,
             CppnOutputs& out);
  void query(const Eigen::Vector3d& p, double r_parent, CppnOutputs& out) {
    query(p, r_parent, nullptr, out);
  }

  /// Queries made so far (for benchmarks and tests).
  long long count() const { return count_; }

 private:
  Network* cppn_;
  double bias_;
  std::array<double, kCppnInputs> in_{};
  long long count_ = 0;
};

}  // namespace robozoo
