#include "evolve/sim/setup/params_check.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace robozoo {
namespace {

std::string message_of(const SimParams& p) {
  try {
    check_sim_params(p);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(SimParamsCheck, DefaultsPass) { EXPECT_NO_THROW(check_sim_params(SimParams{})); }

TEST(SimParamsCheck, NamesTheOffendingField) {
  SimParams p;
  p.dt = 0;
  EXPECT_NE(message_of(p).find("SimParams.dt"), std::string::npos);
  p = SimParams{};
  p.contact_erp = 1.5;
  EXPECT_NE(message_of(p).find("contact_erp"), std::string::npos);
  p = SimParams{};
  p.rolling_contact_fraction = std::nan("");
  EXPECT_NE(message_of(p).find("rolling_contact_fraction"), std::string::npos);
  p = SimParams{};
  p.motor_strength = -1;
  EXPECT_NE(message_of(p).find("motor_strength"), std::string::npos);
  p = SimParams{};
  p.rest_steps = 0;
  EXPECT_NE(message_of(p).find("rest_steps"), std::string::npos);
  p = SimParams{};
  p.max_angular_acceleration = 0;
  EXPECT_NE(message_of(p).find("max_angular_acceleration"), std::string::npos);
}

}  // namespace
}  // namespace robozoo
