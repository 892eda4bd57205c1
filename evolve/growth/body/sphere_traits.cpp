#include "evolve/growth/body/sphere_traits.hpp"

#include <algorithm>

#include "evolve/growth/growth.hpp"

namespace robozoo {

double sphere_radius(double r_parent, double r_scale, const GrowthParams& p) {
  return std::clamp(r_parent * (1.0 + r_scale), p.r_min, p.r_max);
}

double sphere_density(double m, const GrowthParams& p) {
  const double excess = std::max(m, p.t_matter) - p.t_matter;
  return p.rho_min + (p.rho_max - p.rho_min) * excess / (1.0 - p.t_matter);
}

uint8_t sensor_mask(const CppnOutputs& out, bool has_joint, const GrowthParams& p) {
  uint8_t mask = 0;
  if (out[kOutSensorDistance] > p.t_sensor) mask |= kSensorDistance;
  if (out[kOutSensorTouch] > p.t_sensor) mask |= kSensorTouch;
  if (has_joint && out[kOutSensorProprio] > p.t_sensor) mask |= kSensorProprio;
  if (out[kOutSensorTime] > p.t_sensor) mask |= kSensorTime;
  return mask;
}

}  // namespace robozoo
