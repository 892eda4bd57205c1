#include "evolve/growth/params.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <stdexcept>
#include <vector>

namespace robozoo {
namespace {

TEST(GrowthParams, DefaultsAreThePapersAndValid) {
  const GrowthParams p;
  EXPECT_NO_THROW(validate_growth_params(p));
  EXPECT_EQ(p.r_init, 0.1);
  EXPECT_EQ(p.r_min, 0.05);
  EXPECT_EQ(p.r_max, 0.5);
  EXPECT_EQ(p.t_matter, 0.7);
  EXPECT_EQ(p.t_joint, 0.7);
  EXPECT_EQ(p.cloud_points, 629);
  EXPECT_EQ(p.cloud_step, 0.01);
  EXPECT_EQ(p.bound, 2.0);
  EXPECT_EQ(p.touch_tolerance, 1e-9);
}

TEST(GrowthParams, EachBadValueIsRejected) {
  const std::vector<std::function<void(GrowthParams&)>> bad = {
      [](GrowthParams& p) { p.r_min = 0; },
      [](GrowthParams& p) { p.r_max = 0.04; },
      [](GrowthParams& p) { p.r_init = 0.6; },
      [](GrowthParams& p) { p.t_matter = 1.0; },
      [](GrowthParams& p) { p.t_joint = 1.5; },
      [](GrowthParams& p) { p.weight_threshold = -0.1; },
      [](GrowthParams& p) { p.rho_min = 0; },
      [](GrowthParams& p) { p.rho_max = 0.5; },
      [](GrowthParams& p) { p.max_joint_range = -1; },
      [](GrowthParams& p) { p.tau_min = 0; },
      [](GrowthParams& p) { p.tau_max = 0.01; },
      [](GrowthParams& p) { p.cloud_points = 0; },
      [](GrowthParams& p) { p.cloud_step = 0; },
      [](GrowthParams& p) { p.bound = -1; },
      [](GrowthParams& p) { p.max_spheres = 0; },
      [](GrowthParams& p) { p.bias_input = NAN; },
      [](GrowthParams& p) { p.touch_tolerance = -1e-12; },
      [](GrowthParams& p) { p.touch_tolerance = 1e-3; },
      [](GrowthParams& p) { p.touch_tolerance = NAN; },
  };
  for (size_t i = 0; i < bad.size(); ++i) {
    GrowthParams p;
    bad[i](p);
    EXPECT_THROW(validate_growth_params(p), std::invalid_argument) << "case " << i;
  }
}

}  // namespace
}  // namespace robozoo
