#pragma once
// A new sphere's radius, density and sensors from the CPPN outputs at its
// point (paper 2.3; docs/method.md section 2, outputs table).
#include <cstdint>

#include "evolve/growth/body/cppn_probe.hpp"
#include "evolve/growth/params.hpp"

namespace robozoo {

/// r = clamp(r_parent * (1 + r_scale), r_min, r_max) (m).
double sphere_radius(double r_parent, double r_scale, const GrowthParams& p);

/// rho_min + (rho_max - rho_min) (m - T) / (1 - T), with m taken as at least T:
/// a grown sphere always has m > T; the root, which exists whatever its m, gets
/// rho_min when its own m is at or below the threshold (mass per m^3).
double sphere_density(double m, const GrowthParams& p);

/// SensorBit mask of the sensor outputs above t_sensor. The proprioceptive bit
/// only with a joint (Table 1: only spheres jointed to their parent).
uint8_t sensor_mask(const CppnOutputs& out, bool has_joint, const GrowthParams& p);

}  // namespace robozoo
