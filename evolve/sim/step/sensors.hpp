#pragma once
// Sensor values (paper Table 1, docs/method.md section 2), in robot.sensors order:
//   distance = clamp(1 - d / range, 0, 1), d from the sensor sphere's world
//              centre to the target;
//   touch    = 1 while the sphere has any contact the collision rules generate
//              (ground, or a part it is not immediately attached to), else 0;
//   proprio  = hinge angle / half range (not clamped: the stops are soft);
//   time     = sin(2 pi f t).
#include <vector>

#include <Eigen/Core>

#include "evolve/growth/robot.hpp"
#include "evolve/sim/params.hpp"

namespace robozoo {

double distance_sensor_value(const Eigen::Vector3d& sphere_center, const SimParams& params);
double time_sensor_value(double time, const SimParams& params);

/// Fills `out` (resized to robot.sensors.size()). sphere_centers and touching are
/// per sphere; joint_angles per joint; joint_of_sphere maps a sphere to its joint
/// index or -1.
void read_sensors(const Robot& robot, const SimParams& params, const std::vector<Eigen::Vector3d>& sphere_centers,
                  const std::vector<uint8_t>& touching, const std::vector<double>& joint_angles,
                  const std::vector<int>& joint_of_sphere, double time, std::vector<double>& out);

}  // namespace robozoo
