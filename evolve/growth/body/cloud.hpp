#pragma once
// The point cloud cast around a sphere (paper 2.3; docs/method.md section 2 step 2):
// cloud_points points on the horizontal circle of radius r_parent around the
// sphere's centre, point k at angle k * cloud_step (rad) from +x towards +y.
#include <vector>

#include <Eigen/Core>

#include "evolve/growth/params.hpp"

namespace robozoo {

class Cloud {
 public:
  /// Tabulates cos and sin of the params' angles once.
  explicit Cloud(const GrowthParams& p);
  int size() const { return static_cast<int>(cos_.size()); }
  /// Point k of the cloud around `center` with radius r_parent (same z as the centre).
  Eigen::Vector3d point(const Eigen::Vector3d& center, double r_parent, int k) const {
    return {center.x() + r_parent * cos_[k], center.y() + r_parent * sin_[k], center.z()};
  }
  /// cloud_angle(k) = k * cloud_step (rad).
  double angle(int k) const { return static_cast<double>(k) * step_; }

 private:
  double step_;
  std::vector<double> cos_, sin_;
};

}  // namespace robozoo
