#pragma once
// Growth (paper 2.3; docs/method.md section 2 steps 1-7): a pure function from a
// decoded CPPN and parameters to a robot model.
#include "evolve/cppn/network.hpp"
#include "evolve/growth/params.hpp"
#include "evolve/growth/robot.hpp"

namespace robozoo {

/// CPPN output indices (node id minus 9), docs/method.md section 2.
enum CppnOutput : int {
  kOutMatter = 0,
  kOutRadius = 1,
  kOutJoint = 2,
  kOutTheta = 3,
  kOutTau = 4,
  kOutOmega = 5,
  kOutSensorDistance = 6,
  kOutSensorTouch = 7,
  kOutSensorProprio = 8,
  kOutSensorTime = 9,
  kOutWeight = 10,
};
/// CPPN input indices.
enum CppnInput : int {
  kInX = 0,
  kInY = 1,
  kInZ = 2,
  kInRParent = 3,
  kInBias = 4,
  kInSensorDistance = 5,
  kInSensorTouch = 6,
  kInSensorProprio = 7,
  kInSensorTime = 8,
};

/// Grows a robot. `cppn` must have the robot layout (9 inputs, 11 outputs).
/// Not const: querying uses the network's scratch buffers.
Robot grow(Network& cppn, const GrowthParams& params);

/// The r term of paper 2.4 for a finished robot, and whether it is simulated.
/// (Used by grow(); exposed for tests.)
void score_r_term(Robot& robot);

}  // namespace robozoo
