#pragma once
// Hand-built robots shared by the simulation tests (built with the library's
// RobotBuilder; positions in the growth frame, shifted onto the ground).
#include "evolve/sim/robots/robot_builder.hpp"

namespace robozoo::test {

/// One sphere of radius r.
inline Robot single_sphere(double r = 0.2, uint8_t sensors = 0) {
  RobotBuilder b;
  b.add_root({0, 0, 0}, r, 1.0, sensors);
  return b.build();
}

/// Three equal fused spheres in a row along x: rests on all three, cannot tip.
inline Robot rigid_row(double r = 0.2) {
  RobotBuilder b;
  const int a = b.add_root({0, 0, 0}, r);
  const int c = b.add_fused(a, {r, 0, 0}, r);
  b.add_fused(c, {2 * r, 0, 0}, r);
  return b.build();
}

/// A sled (two fused spheres of 0.3 along x, distance and time sensors on the
/// root) with a flipper behind it: sphere 2 hinged about y at (-0.3, 0, 0) with
/// a fused sphere 3 further back, both 0.3. The time sensor drives the motor
/// neuron through `w`: the flipper strokes at time_sensor_frequency and pushes
/// the sled towards +x (measured: about +6 m in 25 s at f = 1 Hz with the
/// default SimParams; no rolling rule fires).
inline Robot flipper_sled(double w = 3.0, double omega = 0.0) {
  RobotBuilder b;
  const double r = 0.3;
  const int a = b.add_root({0, 0, 0}, r, 1.0, kSensorDistance | kSensorTime);
  b.add_fused(a, {r, 0, 0}, r);
  const int j = b.add_jointed(a, {-r, 0, 0}, r, {0, 1, 0}, 0.8, 0.1, omega);
  b.add_fused(j, {-2 * r, 0, 0}, r);
  Robot robot = b.build();
  robot.w_sensor_neuron(sensor_index(robot, 0, SensorType::Time), 0) = w;
  return robot;
}

}  // namespace robozoo::test
