#include "evolve/sim/step/sensors.hpp"
#include "evolve/math/trig.hpp"

#include <algorithm>
#include <cmath>

namespace robozoo {

double distance_sensor_value(const Eigen::Vector3d& c, const SimParams& p) {
  const double d = (c - Eigen::Vector3d(p.target_x, p.target_y, p.target_z)).norm();
  return std::clamp(1.0 - d / p.distance_sensor_range, 0.0, 1.0);
}

double time_sensor_value(double time, const SimParams& p) {
  return math::sin(2.0 * M_PI * p.time_sensor_frequency * time);
}

void read_sensors(const Robot& robot, const SimParams& p, const std::vector<Eigen::Vector3d>& centers,
                  const std::vector<uint8_t>& touching, const std::vector<double>& angles,
                  const std::vector<int>& joint_of_sphere, double time, std::vector<double>& out) {
  out.resize(robot.sensors.size());
  double time_value = 0.0;  // one value for every time sensor of this instant, computed once
  bool time_done = false;
  for (size_t k = 0; k < robot.sensors.size(); ++k) {
    const Sensor& s = robot.sensors[k];
    switch (s.type) {
      case SensorType::Distance: out[k] = distance_sensor_value(centers[s.sphere], p); break;
      case SensorType::Touch: out[k] = touching[s.sphere] ? 1.0 : 0.0; break;
      case SensorType::Proprio: {
        const int j = joint_of_sphere[s.sphere];
        const double range = robot.joints[j].range;
        out[k] = range > 0 ? angles[j] / range : 0.0;
        break;
      }
      case SensorType::Time:
        if (!time_done) {
          time_value = time_sensor_value(time, p);
          time_done = true;
        }
        out[k] = time_value;
        break;
    }
  }
}

}  // namespace robozoo
