#include "evolve/growth/body/cppn_probe.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "evolve/growth/growth.hpp"

namespace robozoo {

CppnProbe::CppnProbe(Network& cppn, double bias_input)
    : cppn_(&cppn), bias_(bias_input), in_(kCppnInputs, 0), out_(kCppnOutputs, 0) {
  if (cppn.num_inputs() != kCppnInputs || cppn.num_outputs() != kCppnOutputs)
    throw std::invalid_argument("growth needs a CPPN with the robot layout (9 inputs, 11 outputs), got " +
                                std::to_string(cppn.num_inputs()) + " inputs and " +
                                std::to_string(cppn.num_outputs()) + " outputs");
}

void CppnProbe::begin(int n) {
  if (n < 0) throw std::invalid_argument("CPPN batch of " + std::to_string(n) + " points");
  if (n > in_.cols()) {  // grow only: later batches reuse the storage
    in_.resize(kCppnInputs, n);
    out_.resize(kCppnOutputs, n);
  }
  n_ = n;
}

void CppnProbe::set(int k, const Eigen::Vector3d& p, double r_parent, const SensorType* one_hot) {
  if (k < 0 || k >= n_) throw std::out_of_range("CPPN batch point " + std::to_string(k) + " of " + std::to_string(n_));
  in_(kInX, k) = p.x();
  in_(kInY, k) = p.y();
  in_(kInZ, k) = p.z();
  in_(kInRParent, k) = r_parent;
  in_(kInBias, k) = bias_;
  in_(kInSensorDistance, k) = in_(kInSensorTouch, k) = in_(kInSensorProprio, k) = in_(kInSensorTime, k) = 0.0;
  if (one_hot) in_(kInSensorDistance + static_cast<int>(*one_hot), k) = 1.0;
}

void CppnProbe::run() {
  cppn_->query_batch(in_.leftCols(n_), out_.leftCols(n_));
  for (int o = 0; o < kCppnOutputs; ++o)
    for (int k = 0; k < n_; ++k)
      if (!std::isfinite(out_(o, k))) out_(o, k) = 0.0;
  count_ += n_;
}

void CppnProbe::query(const Eigen::Vector3d& p, double r_parent, const SensorType* one_hot, CppnOutputs& out) {
  begin(1);
  set(0, p, r_parent, one_hot);
  run();
  outputs(0, out);
}

}  // namespace robozoo
