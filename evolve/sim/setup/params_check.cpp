#include "evolve/sim/setup/params_check.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace robozoo {
namespace {

void require(bool ok, const char* field, const char* range) {
  if (!ok) throw std::invalid_argument(std::string("SimParams.") + field + " must be " + range);
}

}  // namespace

void check_sim_params(const SimParams& p) {
  require(p.steps >= 0, "steps", ">= 0");
  require(p.dt > 0 && std::isfinite(p.dt), "dt", "> 0");
  require(p.gravity >= 0 && std::isfinite(p.gravity), "gravity", ">= 0");
  require(p.quickstep_iterations >= 1, "quickstep_iterations", ">= 1");
  require(p.erp >= 0 && p.erp <= 1, "erp", "in [0, 1]");
  require(p.cfm >= 0 && std::isfinite(p.cfm), "cfm", ">= 0");
  require(p.contact_erp >= 0 && p.contact_erp <= 1, "contact_erp", "in [0, 1]");
  require(p.contact_cfm >= 0 && std::isfinite(p.contact_cfm), "contact_cfm", ">= 0");
  require(p.friction >= 0, "friction", ">= 0");
  require(p.max_contacts >= 1 && p.max_contacts <= 64, "max_contacts", "in [1, 64]");
  require(p.max_correcting_velocity > 0, "max_correcting_velocity", "> 0");
  require(p.servo_gain >= 0 && std::isfinite(p.servo_gain), "servo_gain", ">= 0");
  require(p.servo_max_speed >= 0 && std::isfinite(p.servo_max_speed), "servo_max_speed", ">= 0");
  require(p.motor_strength >= 0 && std::isfinite(p.motor_strength), "motor_strength", ">= 0");
  require(std::isfinite(p.target_x) && std::isfinite(p.target_y) && std::isfinite(p.target_z), "target_x/y/z",
          "finite");
  require(p.distance_sensor_range > 0 && std::isfinite(p.distance_sensor_range), "distance_sensor_range", "> 0");
  require(p.time_sensor_frequency >= 0 && std::isfinite(p.time_sensor_frequency), "time_sensor_frequency", ">= 0");
  require(p.rest_linear_speed >= 0, "rest_linear_speed", ">= 0");
  require(p.rest_angular_speed >= 0, "rest_angular_speed", ">= 0");
  require(p.rest_output_rate >= 0, "rest_output_rate", ">= 0");
  require(p.rest_steps >= 1, "rest_steps", ">= 1");
  require(p.max_linear_acceleration > 0, "max_linear_acceleration", "> 0");
  require(p.max_angular_acceleration > 0, "max_angular_acceleration", "> 0");
  require(p.rolling_contact_fraction >= 0 && p.rolling_contact_fraction <= 1, "rolling_contact_fraction", "in [0, 1]");
  require(p.rolling_spin_threshold >= 0, "rolling_spin_threshold", ">= 0");
}

}  // namespace robozoo
