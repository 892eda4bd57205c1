#include "evolve/growth/cppn_probe.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "evolve/growth/growth.hpp"

namespace robozoo {

CppnProbe::CppnProbe(Network& cppn, double bias_input) : cppn_(&cppn), bias_(bias_input) {
  if (cppn.num_inputs() != kCppnInputs || cppn.num_outputs() != kCppnOutputs)
    throw std::invalid_argument("growth needs a CPPN with the robot layout (9 inputs, 11 outputs), got " +
                                std::to_string(cppn.num_inputs()) + " inputs and " +
                                std::to_string(cppn.num_outputs()) + " outputs");
}

void CppnProbe::query(const Eigen::Vector3d& p, double r_parent, const SensorType* one_hot,
                      CppnOutputs& out) {
  in_[kInX] = p.x();
  in_[kInY] = p.y();
  in_[kInZ] = p.z();
  in_[kInRParent] = r_parent;
  in_[kInBias] = bias_;
  in_[kInSensorDistance] = in_[kInSensorTouch] = in_[kInSensorProprio] = in_[kInSensorTime] = 0.0;
  if (one_hot) in_[kInSensorDistance + static_cast<int>(*one_hot)] = 1.0;
  cppn_->query(in_.data(), out.data());
  for (double& v : out)
    if (!std::isfinite(v)) v = 0.0;
  ++count_;
}

}  // namespace robozoo
