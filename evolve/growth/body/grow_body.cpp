#include "evolve/growth/body/grow_body.hpp"

#include <algorithm>
#include <queue>
#include <utility>
#include <vector>

#include "evolve/growth/body/cloud.hpp"
#include "evolve/growth/growth.hpp"
#include "evolve/growth/body/hinge.hpp"
#include "evolve/growth/body/placement.hpp"
#include "evolve/growth/body/sphere_traits.hpp"

namespace robozoo {

namespace {

/// Queue entry: larger m first; equal m: smaller (earlier) index first.
struct Pending {
  double m;
  int sphere;
};
struct Lower {
  bool operator()(const Pending& a, const Pending& b) const {
    if (a.m != b.m) return a.m < b.m;
    return a.sphere > b.sphere;
  }
};

}  // namespace

GrownBody grow_body(CppnProbe& probe, const GrowthParams& params) {
  const int max_spheres = params.max_spheres;
  GrownBody body;
  body.spheres.reserve(static_cast<size_t>(max_spheres));
  body.motors.reserve(static_cast<size_t>(max_spheres));
  Placement placement(params.bound, max_spheres, params.touch_tolerance);
  const Cloud cloud(params);

  // 1. The root.
  CppnOutputs out;
  {
    Sphere root;
    root.index = 0;
    root.parent = -1;
    root.center = Eigen::Vector3d::Zero();
    root.radius = params.r_init;
    probe.query(root.center, params.r_init, out);
    root.matter = out[kOutMatter];
    root.density = sphere_density(out[kOutMatter], params);
    root.sensors = sensor_mask(out, false, params);
    root.body = 0;
    body.spheres.push_back(root);
    body.motors.push_back(Neuron{0, 0.0, 0.0});
    placement.add_root(root.center, root.radius);
  }

  std::vector<Pending> heap_storage;
  heap_storage.reserve(static_cast<size_t>(max_spheres));
  std::priority_queue<Pending, std::vector<Pending>, Lower> queue(Lower{}, std::move(heap_storage));
  queue.push({body.spheres[0].matter, 0});

  // Per-cloud scratch, allocated once.
  const int n_points = cloud.size();
  std::vector<int> points, order;  // cloud indices queried; batch columns by m
  points.reserve(static_cast<size_t>(n_points));
  order.reserve(static_cast<size_t>(n_points));

  while (!queue.empty() && static_cast<int>(body.spheres.size()) < max_spheres) {
    const int parent = queue.top().sphere;
    queue.pop();
    const Eigen::Vector3d center = body.spheres[parent].center;
    const double r_parent = body.spheres[parent].radius;

    // 2. Query the cloud points, all in one batch. A point that rules (b)-(d)
    //    refuse at every radius is left out: it would be skipped in step 4 whatever
    //    the CPPN says there, and leaving it out changes no other point's outputs.
    points.clear();
    for (int k = 0; k < n_points; ++k)
      if (!placement.refused_at_any_radius(cloud.point(center, r_parent, k), params.r_min, parent)) points.push_back(k);
    const int n_queried = static_cast<int>(points.size());
    probe.begin(n_queried);
    for (int j = 0; j < n_queried; ++j) probe.set(j, cloud.point(center, r_parent, points[j]), r_parent);
    probe.run();
    order.clear();
    for (int j = 0; j < n_queried; ++j)
      if (probe.output(j, kOutMatter) > params.t_matter) order.push_back(j);  // rule (a)
    // 3. By m descending; equal m keep cloud order (batch columns follow it; a
    //    total order, so std::sort gives the stable sort's result without its buffer).
    std::sort(order.begin(), order.end(), [&](int a, int b) {
      const double ma = probe.output(a, kOutMatter), mb = probe.output(b, kOutMatter);
      if (ma != mb) return ma > mb;
      return a < b;
    });

    CppnOutputs o;
    for (int j : order) {
      const int k = points[j];
      probe.outputs(j, o);
      const Eigen::Vector3d p = cloud.point(center, r_parent, k);
      const double r = sphere_radius(r_parent, o[kOutRadius], params);
      const bool jointed = o[kOutJoint] > params.t_joint;
      if (!placement.admissible(p, r, parent, jointed)) continue;

      // 4. Place it.
      Sphere s;
      s.index = static_cast<int>(body.spheres.size());
      s.parent = parent;
      s.center = p;
      s.radius = r;
      s.matter = o[kOutMatter];
      s.density = sphere_density(o[kOutMatter], params);
      s.cloud_angle_index = k;
      s.has_joint = jointed;
      Neuron motor{s.index, 0.0, 0.0};
      if (jointed) {
        s.joint_axis = hinge_axis(p - center, o[kOutTheta]);
        s.joint_range = hinge_range(o[kOutJoint], params);
        motor.tau = motor_tau(o[kOutTau], params);
        motor.omega = motor_omega(o[kOutOmega], params);
      }
      s.sensors = sensor_mask(o, jointed, params);
      s.body = placement.add(p, r, parent, jointed);
      body.spheres[parent].num_children++;
      body.spheres.push_back(s);
      body.motors.push_back(motor);
      queue.push({s.matter, s.index});
      if (static_cast<int>(body.spheres.size()) >= max_spheres) break;
    }
  }
  body.num_components = placement.num_components();
  return body;
}

}  // namespace robozoo
