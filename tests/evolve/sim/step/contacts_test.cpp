#include "evolve/sim/step/contacts.hpp"

#include <gtest/gtest.h>

#include "evolve/sim/robots/robot_builder.hpp"

namespace robozoo {
namespace {

// Chain of bodies 0 - 1 - 2 along x: spheres 0,1 in body 0; 2 in body 1; 3 in body 2.
// Sphere 3 overlaps sphere 0 (centres 0.35 apart, radii 0.2) but not sphere 1.
Robot chain() {
  RobotBuilder b;
  const int a = b.add_root({0, 0, 0}, 0.2);
  b.add_fused(a, {0, 0.2, 0}, 0.2);
  const int j1 = b.add_jointed(a, {0.2, 0, 0}, 0.2, {0, 1, 0}, 0.5);
  b.add_jointed(j1, {0.35, 0, 0}, 0.2, {0, 1, 0}, 0.5);
  return b.build();
}

TEST(Contacts, NeverWithinABodyNorAcrossAJoint) {
  const ContactFinder f(chain());
  // Only body 0 vs body 2 may collide: (0,3) and (1,3), in lexicographic order.
  const std::vector<std::pair<int, int>> expect{{0, 3}, {1, 3}};
  EXPECT_EQ(f.pairs(), expect);
}

TEST(Contacts, RestingSpheresTouchTheGroundAndOverlappingFreeSpheresTouchEachOther) {
  const Robot r = chain();  // every sphere has radius 0.2 and rests on z = 0
  OdeWorld w(r, SimParams{});
  const ContactFinder f(r);
  std::vector<Contact> cs;
  std::vector<uint8_t> touching, ground;
  f.find(w, SimParams{}, cs, touching, ground);
  for (int s = 0; s < 4; ++s) {
    EXPECT_EQ(ground[s], 1) << s;
    EXPECT_EQ(touching[s], 1) << s;
  }
  // Ground contacts come first, by sphere, then the one overlapping free pair (0, 3).
  ASSERT_EQ(cs.size(), 5u);
  for (int s = 0; s < 4; ++s) {
    EXPECT_EQ(cs[s].sphere_a, s);
    EXPECT_EQ(cs[s].sphere_b, -1);
    EXPECT_EQ(cs[s].geom.g1, w.geom(s));
  }
  EXPECT_EQ(cs[4].sphere_a, 0);
  EXPECT_EQ(cs[4].sphere_b, 3);
  EXPECT_NEAR(cs[4].geom.depth, 0.05, 1e-12);
}

TEST(Contacts, SpheresInTheAirTouchNothing) {
  RobotBuilder b;
  b.add_root({0, 0, 1.0}, 0.2);
  const Robot r = b.build(false);
  OdeWorld w(r, SimParams{});
  std::vector<Contact> cs;
  std::vector<uint8_t> touching, ground;
  ContactFinder(r).find(w, SimParams{}, cs, touching, ground);
  EXPECT_TRUE(cs.empty());
  EXPECT_EQ(touching[0], 0);
}

TEST(Contacts, ContactJointsAreCreatedAndEmptied) {
  const Robot r = chain();
  OdeWorld w(r, SimParams{});
  std::vector<Contact> cs;
  std::vector<uint8_t> touching, ground;
  ContactFinder(r).find(w, SimParams{}, cs, touching, ground);
  add_contact_joints(w, SimParams{}, cs);
  // Body 0 has its two hinges plus one contact joint per contact involving it.
  int n0 = 0;
  for (const Contact& c : cs)
    n0 += r.spheres[c.sphere_a].body == 0 || (c.sphere_b >= 0 && r.spheres[c.sphere_b].body == 0);
  EXPECT_EQ(dBodyGetNumJoints(w.body(0)), 1 + n0);
  dJointGroupEmpty(w.contact_group());
  EXPECT_EQ(dBodyGetNumJoints(w.body(0)), 1);
}

}  // namespace
}  // namespace robozoo
