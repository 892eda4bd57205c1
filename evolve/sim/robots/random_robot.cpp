#include "evolve/sim/robots/random_robot.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <Eigen/Geometry>

#include "evolve/sim/robots/robot_builder.hpp"
#include "evolve/math/trig.hpp"

namespace robozoo {

Robot random_robot(Rng& rng, const RandomRobotParams& p) {
  if (p.min_spheres < 1 || p.max_spheres < p.min_spheres)
    throw std::invalid_argument("random_robot: need 1 <= min_spheres <= max_spheres");
  const int target = static_cast<int>(rng.uniform_int(p.min_spheres, p.max_spheres));
  struct Cand {
    int parent;
    Eigen::Vector3d c;
    double r, density;
    bool joint;
    Eigen::Vector3d axis;
    double range;
  };
  std::vector<Cand> sp;
  std::vector<int> body;         // per sphere
  std::vector<int> body_parent;  // per body: the body its joint attaches to, -1 for the root's
  sp.push_back({-1, Eigen::Vector3d::Zero(), rng.uniform(p.root_radius_min, p.root_radius_max),
                rng.uniform(p.density_min, p.density_max), false, Eigen::Vector3d::Zero(), 0.0});
  body.push_back(0);
  body_parent.push_back(-1);
  const auto joined = [&](int a, int b) { return body_parent[a] == b || body_parent[b] == a; };
  for (int attempt = 0; attempt < p.max_attempts && static_cast<int>(sp.size()) < target; ++attempt) {
    const int parent = static_cast<int>(rng.index(sp.size()));
    const double angle = rng.uniform(0.0, 2 * M_PI);
    const Eigen::Vector3d a(math::cos(angle), math::sin(angle), 0.0);
    const Eigen::Vector3d c = sp[parent].c + sp[parent].r * a;
    const double r = std::clamp(sp[parent].r * rng.uniform(0.0, 2.0), p.r_min, p.r_max);
    const bool joint = rng.bernoulli(p.joint_probability);
    if (std::abs(c.x()) > p.bound || std::abs(c.y()) > p.bound) continue;  // (d)
    const int new_body = joint ? static_cast<int>(body_parent.size()) : body[parent];
    bool ok = true;
    for (size_t s = 0; s < sp.size() && ok; ++s) {
      const double d = (sp[s].c - c).norm();
      if (static_cast<int>(s) != parent && d < r) ok = false;  // (b)
      const int b = body[s];
      const bool exempt = b == new_body || (joint ? b == body[parent] : joined(b, new_body));
      if (!exempt && d < r + sp[s].r) ok = false;  // (c)
    }
    if (!ok) continue;
    Eigen::Vector3d axis = Eigen::Vector3d::Zero();
    double range = 0.0;
    if (joint) {
      const Eigen::Vector3d n = a.cross(Eigen::Vector3d::UnitZ()).normalized();
      const double phi = M_PI * rng.uniform(-1.0, 1.0);
      axis = (n * math::cos(phi) + a.cross(n) * math::sin(phi)).normalized();
      range = p.max_joint_range * (1.0 - rng.uniform());  // in (0, max]
      body_parent.push_back(body[parent]);
    }
    sp.push_back({parent, c, r, rng.uniform(p.density_min, p.density_max), joint, axis, range});
    body.push_back(new_body);
  }
  // Prune: a leaf's joint becomes rigid.
  std::vector<int> children(sp.size(), 0);
  for (const Cand& s : sp)
    if (s.parent >= 0) ++children[s.parent];
  RobotBuilder b;
  for (size_t i = 0; i < sp.size(); ++i) {
    Cand& s = sp[i];
    if (s.joint && children[i] == 0) s.joint = false;
    uint8_t sensors = 0;
    for (uint8_t bit : {kSensorDistance, kSensorTouch, kSensorProprio, kSensorTime}) {
      if (!rng.bernoulli(p.sensor_probability)) continue;
      if (bit == kSensorProprio && !s.joint) continue;
      sensors |= bit;
    }
    if (i == 0)
      b.add_root(s.c, s.r, s.density, sensors);
    else if (s.joint)
      b.add_jointed(s.parent, s.c, s.r, s.axis, s.range, rng.uniform(p.tau_min, p.tau_max),
                    rng.uniform(-p.bias_max, p.bias_max), s.density, sensors);
    else
      b.add_fused(s.parent, s.c, s.r, s.density, sensors);
  }
  Robot robot = b.build(true);
  const auto weight = [&] {
    if (!rng.bernoulli(p.link_probability)) return 0.0;
    const double v = rng.uniform(-1.0, 1.0);
    return std::abs(v) > 0.2 ? v * p.weight_max : 0.0;
  };
  for (int k = 0; k < robot.w_sensor_neuron.rows(); ++k)
    for (int i = 0; i < robot.w_sensor_neuron.cols(); ++i) robot.w_sensor_neuron(k, i) = weight();
  for (int j = 0; j < robot.w_neuron_neuron.rows(); ++j)
    for (int i = 0; i < robot.w_neuron_neuron.cols(); ++i) robot.w_neuron_neuron(j, i) = weight();
  robot.simulate = true;
  return robot;
}

}  // namespace robozoo
