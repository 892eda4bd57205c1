#pragma once
// Builds Robot models by hand, following the conventions of
// evolve/growth/robot.hpp: bodies numbered by their first sphere in growth
// order, joints and motor neurons in growth order of their spheres, sensors by
// sphere then type, a vertical shift that rests the largest sphere on z = 0.
// For tests, benchmarks and the random-robot generator; growth builds its own
// robots from CPPNs. No pruning happens here: what is added is what is built.
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "evolve/growth/robot.hpp"

namespace robozoo {

class RobotBuilder {
 public:
  /// The root sphere (index 0). Centre in the growth frame (m), radius (m),
  /// density (mass per m^3), sensors (SensorBit mask).
  int add_root(const Eigen::Vector3d& center, double radius, double density = 1.0, uint8_t sensors = 0);
  /// A sphere fused to `parent` (same rigid body). Returns its index.
  int add_fused(int parent, const Eigen::Vector3d& center, double radius, double density = 1.0, uint8_t sensors = 0);
  /// A sphere joined to `parent` by a hinge at its own centre: unit axis, half
  /// range (rad), motor neuron time constant (s) and bias. Returns its index.
  int add_jointed(int parent, const Eigen::Vector3d& center, double radius, const Eigen::Vector3d& axis, double range,
                  double tau = 0.5, double omega = 0.0, double density = 1.0, uint8_t sensors = 0);
  int size() const { return static_cast<int>(spheres_.size()); }

  /// The model, with zero weight matrices of the right sizes. When
  /// rest_on_ground, every centre moves by the same dz so that the largest
  /// sphere (the first of equal ones) rests on z = 0; else positions stay as given.
  Robot build(bool rest_on_ground = true) const;

 private:
  struct Spec {
    Sphere sphere;
    double tau = 0.5, omega = 0.0;
  };
  int add(Spec s);
  static Spec child_spec(int parent, const Eigen::Vector3d& center, double radius, double density, uint8_t sensors);
  std::vector<Spec> spheres_;
};

/// Index into robot.sensors of the sensor of `type` on `sphere`, or -1.
int sensor_index(const Robot& robot, int sphere, SensorType type);
/// Index of the motor neuron on `sphere`, or -1.
int neuron_index(const Robot& robot, int sphere);

}  // namespace robozoo
