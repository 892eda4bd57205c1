#include "evolve/sim/setup/world.hpp"

#include <cmath>
#include <stdexcept>

#include "evolve/sim/setup/ode_init.hpp"

namespace robozoo {

static_assert(sizeof(dReal) == sizeof(double), "robozoo needs ODE built in double precision");

double sphere_mass(const Sphere& s) { return s.density * 4.0 / 3.0 * M_PI * s.radius * s.radius * s.radius; }

OdeWorld::OdeWorld(const Robot& robot, const SimParams& p) {
  ensure_ode_initialized();
  world_ = dWorldCreate();
  contact_group_ = dJointGroupCreate(0);
  dWorldSetGravity(world_, 0, 0, -p.gravity);
  dWorldSetERP(world_, p.erp);
  dWorldSetCFM(world_, p.cfm);
  dWorldSetQuickStepNumIterations(world_, p.quickstep_iterations);
  dWorldSetContactMaxCorrectingVel(world_, p.max_correcting_velocity);
  dWorldSetAutoDisableFlag(world_, 0);
  ground_ = dCreatePlane(nullptr, 0, 0, 1, 0);

  const int nb = robot.num_bodies;
  const auto& sp = robot.spheres;
  bodies_.resize(nb);
  body_mass_.assign(nb, 0.0);
  geoms_.resize(sp.size());
  // Combined mass per body, about a reference point (the body's first sphere),
  // then moved so that the centre of mass is the body origin, as ODE requires.
  std::vector<dMass> mass(nb);
  std::vector<int> first(nb, -1);
  for (auto& m : mass) dMassSetZero(&m);
  for (const Sphere& s : sp) {
    if (first[s.body] < 0) first[s.body] = s.index;
    const Eigen::Vector3d rel = s.center - sp[first[s.body]].center;
    dMass m;
    dMassSetSphere(&m, s.density, s.radius);
    dMassTranslate(&m, rel.x(), rel.y(), rel.z());
    dMassAdd(&mass[s.body], &m);
  }
  std::vector<Eigen::Vector3d> com(nb);
  for (int b = 0; b < nb; ++b) {
    dMass& m = mass[b];
    com[b] = sp[first[b]].center + Eigen::Vector3d(m.c[0], m.c[1], m.c[2]);
    dMassTranslate(&m, -m.c[0], -m.c[1], -m.c[2]);
    m.c[0] = m.c[1] = m.c[2] = 0;  // exactly at the origin (translation leaves ~1e-17)
    bodies_[b] = dBodyCreate(world_);
    dBodySetPosition(bodies_[b], com[b].x(), com[b].y(), com[b].z());
    dBodySetMass(bodies_[b], &m);
    body_mass_[b] = m.mass;
    total_mass_ += m.mass;
  }
  for (const Sphere& s : sp) {
    dGeomID g = dCreateSphere(nullptr, s.radius);
    dGeomSetBody(g, bodies_[s.body]);
    const Eigen::Vector3d off = s.center - com[s.body];
    dGeomSetOffsetPosition(g, off.x(), off.y(), off.z());
    geoms_[s.index] = g;
  }
  for (const Joint& j : robot.joints) {
    dJointID h = dJointCreateHinge(world_, nullptr);
    dJointAttach(h, bodies_[j.parent_body], bodies_[j.child_body]);
    const Eigen::Vector3d& a = sp[j.sphere].center;
    dJointSetHingeAnchor(h, a.x(), a.y(), a.z());
    dJointSetHingeAxis(h, j.axis.x(), j.axis.y(), j.axis.z());  // angle 0 = as grown
    dJointSetHingeParam(h, dParamLoStop, -j.range);
    dJointSetHingeParam(h, dParamHiStop, j.range);
    dJointSetHingeParam(h, dParamVel, 0);
    dJointSetHingeParam(h, dParamFMax, 0);
    hinges_.push_back(h);
  }
}

OdeWorld::~OdeWorld() {
  for (dGeomID g : geoms_) dGeomDestroy(g);
  if (ground_) dGeomDestroy(ground_);
  if (contact_group_) dJointGroupDestroy(contact_group_);
  if (world_) dWorldDestroy(world_);  // also destroys bodies and hinges
}

Eigen::Vector3d OdeWorld::sphere_center(int sphere) const {
  const dReal* p = dGeomGetPosition(geoms_[sphere]);
  return {p[0], p[1], p[2]};
}

Eigen::Vector3d OdeWorld::center_of_mass() const {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (size_t b = 0; b < bodies_.size(); ++b) {
    const dReal* p = dBodyGetPosition(bodies_[b]);
    c += body_mass_[b] * Eigen::Vector3d(p[0], p[1], p[2]);
  }
  return c / total_mass_;
}

}  // namespace robozoo
