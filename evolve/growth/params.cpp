#include "evolve/growth/params.hpp"

#include <stdexcept>
#include <string>

namespace robozoo {

std::string weight_mapping_name(WeightMapping m) { return m == WeightMapping::Rescaled ? "rescaled" : "proportional"; }

WeightMapping weight_mapping_from_name(const std::string& s) {
  if (s == "rescaled") return WeightMapping::Rescaled;
  if (s == "proportional") return WeightMapping::Proportional;
  throw std::invalid_argument("unknown weight mapping '" + s + "' (use rescaled, proportional)");
}

void validate_growth_params(const GrowthParams& p) {
  auto fail = [](const std::string& what) { throw std::invalid_argument("growth parameters: " + what); };
  const double reals[] = {
      p.r_init,           p.r_min,      p.r_max,      p.t_matter,        p.t_joint, p.t_sensor,
      p.weight_threshold, p.rho_min,    p.rho_max,    p.max_joint_range, p.tau_min, p.tau_max,
      p.bias_max,         p.weight_max, p.bias_input, p.cloud_step,      p.bound,   p.touch_tolerance};
  for (double v : reals)
    if (!std::isfinite(v)) fail("every value must be finite");
  if (!(p.r_min > 0)) fail("r_min must be positive");
  if (!(p.r_min <= p.r_max)) fail("r_min must not exceed r_max");
  if (!(p.r_min <= p.r_init && p.r_init <= p.r_max)) fail("r_init must lie in [r_min, r_max]");
  // (m - T) / (1 - T) and (j - T) / (1 - T) divide by 1 - T.
  if (!(p.t_matter < 1)) fail("t_matter must be below 1");
  if (!(p.t_joint < 1)) fail("t_joint must be below 1");
  if (!(p.weight_threshold >= 0)) fail("weight_threshold must not be negative");
  // The rescaled mapping divides by 1 - weight_threshold.
  if (p.weight_mapping == WeightMapping::Rescaled && !(p.weight_threshold < 1))
    fail("weight_threshold must be below 1 with the rescaled weight mapping");
  if (!(p.rho_min > 0 && p.rho_min <= p.rho_max)) fail("need 0 < rho_min <= rho_max");
  if (!(p.max_joint_range >= 0)) fail("max_joint_range must not be negative");
  if (!(p.tau_min > 0 && p.tau_min <= p.tau_max)) fail("need 0 < tau_min <= tau_max");
  if (p.cloud_points < 1) fail("cloud_points must be at least 1");
  if (!(p.cloud_step > 0)) fail("cloud_step must be positive");
  if (!(p.bound >= 0)) fail("bound must not be negative");
  if (p.max_spheres < 1) fail("max_spheres must be at least 1");
  if (!(p.touch_tolerance >= 0 && p.touch_tolerance < 1e-3)) fail("touch_tolerance must lie in [0, 1e-3)");
}

}  // namespace robozoo
