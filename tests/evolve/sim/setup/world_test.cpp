#include "evolve/sim/setup/world.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "evolve/sim/robots/robot_builder.hpp"

namespace robozoo {
namespace {

// Body 0: spheres 0 (r 0.2, density 1) and 1 (r 0.1, density 3); body 1: spheres 2, 3.
Robot two_bodies() {
  RobotBuilder b;
  const int a = b.add_root({0, 0, 0}, 0.2, 1.0);
  b.add_fused(a, {0, 0.2, 0}, 0.1, 3.0);
  const int j = b.add_jointed(a, {0.2, 0, 0}, 0.15, {0, 1, 0}, 0.6);
  b.add_fused(j, {0.35, 0, 0}, 0.1, 2.0);
  return b.build();
}

TEST(World, SphereMassIsDensityTimesVolume) {
  Sphere s;
  s.radius = 0.5;
  s.density = 3.0;
  EXPECT_NEAR(sphere_mass(s), 3.0 * 4.0 / 3.0 * M_PI * 0.125, 1e-15);
}

TEST(World, BodiesSitAtTheirCentresOfMassWithCombinedMass) {
  const Robot r = two_bodies();
  const SimParams p;
  OdeWorld w(r, p);
  ASSERT_EQ(w.num_bodies(), 2);
  for (int b = 0; b < 2; ++b) {
    double m = 0;
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (const Sphere& s : r.spheres)
      if (s.body == b) {
        m += sphere_mass(s);
        c += sphere_mass(s) * s.center;
      }
    c /= m;
    EXPECT_NEAR(w.body_mass(b), m, 1e-14);
    const dReal* pos = dBodyGetPosition(w.body(b));
    EXPECT_NEAR((Eigen::Vector3d(pos[0], pos[1], pos[2]) - c).norm(), 0.0, 1e-14);
    dMass dm;
    dBodyGetMass(w.body(b), &dm);
    EXPECT_EQ(dm.c[0], 0.0);
    EXPECT_EQ(dm.c[1], 0.0);
    EXPECT_EQ(dm.c[2], 0.0);
  }
  EXPECT_NEAR(w.total_mass(), w.body_mass(0) + w.body_mass(1), 1e-15);
  // Every geom sits at its sphere's centre.
  for (const Sphere& s : r.spheres) EXPECT_NEAR((w.sphere_center(s.index) - s.center).norm(), 0.0, 1e-14);
}

TEST(World, InertiaIsTheSumOfTheSpheresAboutTheCentreOfMass) {
  // Two equal spheres along x: Ixx = 2 * 2/5 m r^2, Iyy = Ixx + 2 m d^2 (d = half the spacing).
  RobotBuilder b;
  b.add_fused(b.add_root({0, 0, 0}, 0.2), {0.2, 0, 0}, 0.2);
  const Robot r = b.build();
  OdeWorld w(r, SimParams{});
  dMass dm;
  dBodyGetMass(w.body(0), &dm);
  const double m = sphere_mass(r.spheres[0]);
  EXPECT_NEAR(dm.I[0], 2 * 0.4 * m * 0.04, 1e-14);                 // I(0,0)
  EXPECT_NEAR(dm.I[5], 2 * 0.4 * m * 0.04 + 2 * m * 0.01, 1e-14);  // I(1,1), row stride 4
}

TEST(World, HingeIsAnchoredAtTheChildSphereWithStopsAtTheRange) {
  const Robot r = two_bodies();
  OdeWorld w(r, SimParams{});
  ASSERT_EQ(w.num_joints(), 1);
  dVector3 a, ax;
  dJointGetHingeAnchor(w.hinge(0), a);
  dJointGetHingeAxis(w.hinge(0), ax);
  EXPECT_NEAR((Eigen::Vector3d(a[0], a[1], a[2]) - r.spheres[2].center).norm(), 0.0, 1e-14);
  EXPECT_NEAR(ax[1], 1.0, 1e-14);
  EXPECT_DOUBLE_EQ(dJointGetHingeAngle(w.hinge(0)), 0.0);
  EXPECT_DOUBLE_EQ(dJointGetHingeParam(w.hinge(0), dParamLoStop), -0.6);
  EXPECT_DOUBLE_EQ(dJointGetHingeParam(w.hinge(0), dParamHiStop), 0.6);
  EXPECT_EQ(dJointGetBody(w.hinge(0), 0), w.body(0));
  EXPECT_EQ(dJointGetBody(w.hinge(0), 1), w.body(1));
}

TEST(World, CentreOfMassIsMassWeighted) {
  const Robot r = two_bodies();
  OdeWorld w(r, SimParams{});
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  double m = 0;
  for (const Sphere& s : r.spheres) {
    c += sphere_mass(s) * s.center;
    m += sphere_mass(s);
  }
  EXPECT_NEAR((w.center_of_mass() - c / m).norm(), 0.0, 1e-14);
}

}  // namespace
}  // namespace robozoo
