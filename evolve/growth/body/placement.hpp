#pragma once
// Placement rules (b), (c), (d) of paper 2.3 (docs/method.md section 2 step 3), over
// the spheres placed so far and their rigid components.
//
// Rigid components during growth: the root starts component 0. A fused sphere
// joins its parent's component; a jointed sphere starts a new component, joined
// by its hinge to the parent's component. The components and hinges form a tree
// (each component but the root's is joined to exactly one earlier component), so
// "directly joined" means parent or child in that tree.
//
// Our reading of rule (c), "no sphere belonging to a different rigid component
// (with the exception of those directly connected by a joint) will interpenetrate
// this new sphere": let C be the new sphere's component (the parent's component
// P when fused; a new component joined only to P when jointed). The new sphere may
// overlap spheres of C itself and of components directly joined to C: when
// jointed, that is P alone; when fused, P, P's parent component and P's child
// components. Every other sphere q must satisfy |p - q| >= r + r_q ("interpenetrate"
// is strict overlap; touching is allowed).
// Rule (b): no sphere other than the parent has its centre at distance < r from p.
// Rule (d): |p.x| <= bound and |p.y| <= bound.
//
// Touching is decided by the rule, not by rounding: with e = touch_tolerance
// (relative), with d2 = dx*dx + dy*dy + dz*dz from the centres' coordinates,
//   (b) refuses when d2 < ((1 - e) r)^2,
//   (c) refuses when d2 < ((1 - e) (r + r_q))^2,
//   (d) refuses when |x| or |y| > (1 + e) bound.
// Spheres that touch in exact geometry (a chain along one cloud angle touches its
// grandparent) carry coordinates rounded ~1e-15 m apart, far inside e = 1e-9.
//
// A linear scan over contiguous arrays with early exit: growth places at most
// max_spheres spheres, so a check costs at most max_spheres distance tests and no
// allocation; a grid would not pay for itself at this size.
#include <vector>

#include <Eigen/Core>

namespace robozoo {

class Placement {
 public:
  /// `capacity` spheres are reserved (no allocation while placing up to that many).
  /// touch_tolerance: relative tolerance of the three tests, in [0, 1e-3).
  Placement(double bound, int capacity, double touch_tolerance);

  /// Places the root (component 0). Must be the first sphere.
  void add_root(const Eigen::Vector3d& center, double radius);

  /// Rules (b), (c) and (d) for a sphere of `radius` at p attached to sphere
  /// `parent`, fused (jointed = false) or by a hinge.
  bool admissible(const Eigen::Vector3d& p, double radius, int parent, bool jointed) const;

  /// True when admissible(p, radius, parent, jointed) is false for every radius
  /// >= r_min and both joint choices, now and after any further add(). That is
  /// exactly !admissible(p, r_min, parent, false): each test's limit grows with
  /// the radius (rounding is monotone, so also in floating point), a fused sphere
  /// is exempt from (c) wherever a jointed one is, and further spheres only add
  /// tests. Growth leaves such cloud points out of its CPPN queries: whatever the
  /// CPPN says there, they could not change the robot.
  bool refused_at_any_radius(const Eigen::Vector3d& p, double r_min, int parent) const;

  /// Places a sphere (no checks); returns its component.
  int add(const Eigen::Vector3d& p, double radius, int parent, bool jointed);

  int size() const { return static_cast<int>(r_.size()); }
  int component(int sphere) const { return comp_[sphere]; }
  int num_components() const { return static_cast<int>(comp_parent_.size()); }
  /// The component a component is hinged to; -1 for the root's component.
  int component_parent(int c) const { return comp_parent_[c]; }
  /// True if components c and d are joined by one hinge.
  bool directly_joined(int c, int d) const { return comp_parent_[c] == d || comp_parent_[d] == c; }

 private:
  double bound_;    ///< (1 + e) * bound (m)
  double shrink2_;  ///< (1 - e)^2
  std::vector<double> x_, y_, z_, r_;
  std::vector<int> comp_;
  std::vector<int> comp_parent_;
};

}  // namespace robozoo
