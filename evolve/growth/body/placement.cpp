#include "evolve/growth/body/placement.hpp"

#include <cmath>
#include <stdexcept>

namespace robozoo {

Placement::Placement(double bound, int capacity, double touch_tolerance)
    : bound_((1.0 + touch_tolerance) * bound), shrink2_((1.0 - touch_tolerance) * (1.0 - touch_tolerance)) {
  if (!(touch_tolerance >= 0 && touch_tolerance < 1e-3))
    throw std::invalid_argument("Placement: touch_tolerance must lie in [0, 1e-3)");
  const size_t n = capacity > 0 ? static_cast<size_t>(capacity) : 0;
  x_.reserve(n);
  y_.reserve(n);
  z_.reserve(n);
  r_.reserve(n);
  comp_.reserve(n);
  comp_parent_.reserve(n);
}

void Placement::add_root(const Eigen::Vector3d& center, double radius) {
  if (!r_.empty()) throw std::logic_error("Placement::add_root: the root must be the first sphere");
  x_.push_back(center.x());
  y_.push_back(center.y());
  z_.push_back(center.z());
  r_.push_back(radius);
  comp_.push_back(0);
  comp_parent_.push_back(-1);
}

bool Placement::admissible(const Eigen::Vector3d& p, double radius, int parent, bool jointed) const {
  // (d) the bounding square.
  if (!(std::abs(p.x()) <= bound_ && std::abs(p.y()) <= bound_)) return false;
  const int pc = comp_[parent];
  const int grand = comp_parent_[pc];
  const double r2 = shrink2_ * (radius * radius);
  const int n = size();
  for (int q = 0; q < n; ++q) {
    const double dx = p.x() - x_[q], dy = p.y() - y_[q], dz = p.z() - z_[q];
    const double d2 = dx * dx + dy * dy + dz * dz;
    // (b) no centre other than the parent's closer than r.
    if (q != parent && d2 < r2) return false;
    // (c) no interpenetration with a component not directly joined to the new one.
    const int c = comp_[q];
    const bool exempt = jointed ? c == pc : (c == pc || c == grand || comp_parent_[c] == pc);
    if (!exempt) {
      const double reach = radius + r_[q];
      if (d2 < shrink2_ * (reach * reach)) return false;
    }
  }
  return true;
}

bool Placement::refused_at_any_radius(const Eigen::Vector3d& p, double r_min, int parent) const {
  return !admissible(p, r_min, parent, false);
}

int Placement::add(const Eigen::Vector3d& p, double radius, int parent, bool jointed) {
  if (parent < 0 || parent >= size()) throw std::logic_error("Placement::add: no such parent sphere");
  int c = comp_[parent];
  if (jointed) {
    comp_parent_.push_back(c);
    c = num_components() - 1;
  }
  x_.push_back(p.x());
  y_.push_back(p.y());
  z_.push_back(p.z());
  r_.push_back(radius);
  comp_.push_back(c);
  return c;
}

}  // namespace robozoo
