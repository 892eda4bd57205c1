#pragma once
// Querying the robot CPPN (inputs x, y, z, r_parent, bias, four sensor one-hots;
// eleven outputs), a batch of points at a time: growth sets every point of a
// cloud, or every weight query of a robot, then runs them together through the
// network's batched path. No allocation once the batch has reached its largest size.
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

  /// Starts a batch of n points (n >= 0), all inputs unset.
  void begin(int n);
  /// Sets point k of the batch: position p, the r_parent input, and `one_hot`
  /// sets that sensor type's input to 1 (weight queries from a sensor), nullptr for none.
  void set(int k, const Eigen::Vector3d& p, double r_parent, const SensorType* one_hot = nullptr);
  /// Queries every point of the batch. A non-finite output (possible only with
  /// unbounded activations such as Linear in a recurrent loop) is read as 0, "no
  /// signal", so that every threshold and mapping downstream sees a number.
  void run();
  /// Output o of point k of the last run.
  double output(int k, int o) const { return out_(o, k); }
  /// All outputs of point k of the last run.
  void outputs(int k, CppnOutputs& out) const {
    for (int o = 0; o < kCppnOutputs; ++o) out[o] = out_(o, k);
  }

  /// One point: a batch of one (begin, set, run, outputs).
  void query(const Eigen::Vector3d& p, double r_parent, const SensorType* one_hot, CppnOutputs& out);
  void query(const Eigen::Vector3d& p, double r_parent, CppnOutputs& out) { query(p, r_parent, nullptr, out); }

  /// Points queried so far (for benchmarks and tests).
  long long count() const { return count_; }

 private:
  Network* cppn_;
  double bias_;
  int n_ = 0;
  QueryArray in_, out_;  // kCppnInputs / kCppnOutputs x capacity
  long long count_ = 0;
};

}  // namespace robozoo
