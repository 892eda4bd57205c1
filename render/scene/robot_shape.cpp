#include "render/scene/robot_shape.hpp"

#include <algorithm>
#include <stdexcept>

#include "runlog/read/message_collector.hpp"

namespace robozoo::render {

std::vector<SphereDraw> RobotShape::at(const std::vector<Eigen::Vector3d>& centers) const {
  if (centers.size() != radius.size())
    throw std::invalid_argument("RobotShape::at: " + std::to_string(centers.size()) + " centres for " +
                                std::to_string(radius.size()) + " spheres");
  std::vector<SphereDraw> out(centers.size());
  for (size_t i = 0; i < centers.size(); ++i) out[i] = SphereDraw{centers[i], radius[i], leaf[i]};
  return out;
}

RobotShape shape_from_morphology(const morphology_t& m) {
  const std::string bad = morphology_problem(m);
  if (!bad.empty()) throw std::invalid_argument("genome " + std::to_string(m.genome_id) + ": " + bad);
  RobotShape s;
  s.leaf = leaf_spheres(m);
  for (const sphere_t& sp : m.spheres) {
    s.radius.push_back(sp.radius);
    s.start.emplace_back(sp.center[0], sp.center[1], sp.center[2]);
    s.mass.push_back(std::max(sp.density, 0.0) * 4.0 / 3.0 * 3.14159265358979323846 * sp.radius * sp.radius *
                     sp.radius);
  }
  return s;
}

Eigen::Vector3d RobotShape::mass_center(const std::vector<Eigen::Vector3d>& centers) const {
  if (centers.size() != mass.size())
    throw std::invalid_argument("RobotShape::mass_center: " + std::to_string(centers.size()) + " centres for " +
                                std::to_string(mass.size()) + " spheres");
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  double total = 0.0;
  for (size_t i = 0; i < centers.size(); ++i) {
    sum += mass[i] * centers[i];
    total += mass[i];
  }
  return total > 0 ? Eigen::Vector3d(sum / total) : volume_center(centers, radius);
}

Eigen::Vector3d volume_center(const std::vector<Eigen::Vector3d>& centers, const std::vector<double>& radii) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  double total = 0.0;
  for (size_t i = 0; i < centers.size() && i < radii.size(); ++i) {
    const double v = radii[i] * radii[i] * radii[i];
    sum += v * centers[i];
    total += v;
  }
  return total > 0 ? Eigen::Vector3d(sum / total) : Eigen::Vector3d::Zero();
}

}  // namespace robozoo::render
