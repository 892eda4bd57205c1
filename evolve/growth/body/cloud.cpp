#include "evolve/growth/body/cloud.hpp"
#include "evolve/math/trig.hpp"

#include <cmath>

namespace robozoo {

Cloud::Cloud(const GrowthParams& p) : step_(p.cloud_step) {
  cos_.resize(static_cast<size_t>(p.cloud_points));
  sin_.resize(static_cast<size_t>(p.cloud_points));
  for (int k = 0; k < p.cloud_points; ++k) {
    cos_[k] = math::cos(angle(k));
    sin_[k] = math::sin(angle(k));
  }
}

}  // namespace robozoo
