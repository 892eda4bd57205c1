#include "evolve/sim/step/contacts.hpp"

#include <algorithm>
#include <set>

namespace robozoo {

ContactFinder::ContactFinder(const Robot& robot) {
  std::set<std::pair<int, int>> jointed;
  for (const Joint& j : robot.joints)
    jointed.insert({std::min(j.parent_body, j.child_body), std::max(j.parent_body, j.child_body)});
  const auto& sp = robot.spheres;
  radius_.resize(sp.size());
  for (size_t i = 0; i < sp.size(); ++i) radius_[i] = sp[i].radius;
  for (size_t i = 0; i < sp.size(); ++i)
    for (size_t j = i + 1; j < sp.size(); ++j) {
      const int a = sp[i].body, b = sp[j].body;
      if (a == b || jointed.count({std::min(a, b), std::max(a, b)})) continue;
      pairs_.push_back({static_cast<int>(i), static_cast<int>(j)});
    }
}

void ContactFinder::find(const OdeWorld& world, const SimParams& params, std::vector<Contact>& out,
                         std::vector<uint8_t>& touching, std::vector<uint8_t>& on_ground) const {
  out.clear();
  const int n = world.num_spheres();
  touching.assign(n, 0);
  on_ground.assign(n, 0);
  const int cap = std::max(1, std::min(params.max_contacts, 64));
  dContactGeom buf[64];
  // Ground: the same test as dCollideSpherePlane (depth = r - z >= 0), so that
  // skipping dCollide never drops a contact ODE would report.
  center_.resize(3 * static_cast<size_t>(n));
  for (int s = 0; s < n; ++s) {
    const dReal* p = dGeomGetPosition(world.geom(s));
    std::copy(p, p + 3, &center_[3 * s]);
  }
  for (int s = 0; s < n; ++s) {
    if (radius_[s] - center_[3 * s + 2] < 0) continue;
    const int k = dCollide(world.geom(s), world.ground(), cap, buf, sizeof(dContactGeom));
    for (int c = 0; c < k; ++c) out.push_back({buf[c], s, -1});
    if (k > 0) touching[s] = on_ground[s] = 1;
  }
  for (const auto& [i, j] : pairs_) {
    const double* a = &center_[3 * i];
    const double* b = &center_[3 * j];
    const double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
    const double r = radius_[i] + radius_[j];
    if (dx * dx + dy * dy + dz * dz > r * r * (1 + 1e-12)) continue;  // dCollide decides the rest
    const int k = dCollide(world.geom(i), world.geom(j), cap, buf, sizeof(dContactGeom));
    for (int c = 0; c < k; ++c) out.push_back({buf[c], i, j});
    if (k > 0) touching[i] = touching[j] = 1;
  }
}

void add_contact_joints(const OdeWorld& world, const SimParams& params, const std::vector<Contact>& contacts) {
  for (const Contact& c : contacts) {
    dContact ct{};
    ct.surface.mode = dContactSoftERP | dContactSoftCFM | dContactApprox1;
    ct.surface.mu = params.friction;
    ct.surface.soft_erp = params.contact_erp;
    ct.surface.soft_cfm = params.contact_cfm;
    ct.geom = c.geom;
    dJointID j = dJointCreateContact(world.world(), world.contact_group(), &ct);
    dJointAttach(j, dGeomGetBody(c.geom.g1), dGeomGetBody(c.geom.g2));
  }
}

}  // namespace robozoo
