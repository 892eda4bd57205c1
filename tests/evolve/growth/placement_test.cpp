#include "evolve/growth/placement.hpp"

#include <gtest/gtest.h>

namespace robozoo {
namespace {

using V = Eigen::Vector3d;

TEST(Placement, RuleDBoundingSquareIsInclusive) {
  Placement pl(2.0, 10);
  pl.add_root(V(1.9, 0, 0), 0.1);
  EXPECT_TRUE(pl.admissible(V(2.0, 0, 0), 0.05, 0, false));
  EXPECT_FALSE(pl.admissible(V(2.0 + 1e-12, 0, 0), 0.05, 0, false));
  Placement pl2(2.0, 10);
  pl2.add_root(V(0, -1.95, 0), 0.1);
  EXPECT_FALSE(pl2.admissible(V(0, -2.05, 0), 0.05, 0, false));
}

TEST(Placement, RuleBNoCentreButTheParentsCloserThanR) {
  Placement pl(2.0, 10);
  pl.add_root(V(0, 0, 0), 0.1);
  EXPECT_EQ(pl.add(V(0.1, 0, 0), 0.1, 0, false), 0);  // fused: same component, (c) never applies
  // Attached to the root, a centre 0.05 from sphere 1's is too close for r = 0.1;
  // the parent's own centre may be as close as it likes.
  EXPECT_FALSE(pl.admissible(V(0.1, 0.05, 0), 0.1, 0, false));
  EXPECT_TRUE(pl.admissible(V(0.0, 0.05, 0), 0.1, 0, false));  // 0.05 from the root (parent)
  // Attached to sphere 1, the root is "another sphere": its centre is 0.2 from
  // (0.2, 0). Exactly r away is not "closer than r".
  EXPECT_TRUE(pl.admissible(V(0.2, 0, 0), 0.2, 1, false));
  EXPECT_FALSE(pl.admissible(V(0.2, 0, 0), 0.21, 1, false));
}

TEST(Placement, RuleCSiblingComponentsMayNotInterpenetrate) {
  Placement pl(2.0, 10);
  pl.add_root(V(0, 0, 0), 0.1);
  EXPECT_EQ(pl.add(V(0.1, 0, 0), 0.05, 0, true), 1);  // component 1, joined to 0
  EXPECT_EQ(pl.num_components(), 2);
  EXPECT_TRUE(pl.directly_joined(0, 1));
  // Another jointed child of the root: a sibling component, not joined to 1.
  // Centres 0.08 apart (> r = 0.05: rule (b) holds), radii 0.05 + 0.05 = 0.1.
  EXPECT_FALSE(pl.admissible(V(0.1, 0.08, 0), 0.05, 0, true));
  EXPECT_TRUE(pl.admissible(V(0.1, 0.1, 0), 0.05, 0, true));  // touching is allowed
  // Fused to the root instead, it joins component 0, which is joined to 1.
  EXPECT_TRUE(pl.admissible(V(0.1, 0.08, 0), 0.05, 0, false));
}

TEST(Placement, RuleCFusedSphereMayOverlapParentsChildAndParentComponents) {
  // Components 0 - 1 - 2 in a chain of hinges.
  Placement pl(2.0, 10);
  pl.add_root(V(0, 0, 0), 0.1);                       // sphere 0, component 0
  ASSERT_EQ(pl.add(V(0.3, 0, 0), 0.1, 0, true), 1);   // sphere 1, component 1, hinged to 0
  ASSERT_EQ(pl.add(V(0.3, 0.3, 0), 0.1, 1, true), 2); // sphere 2, component 2, hinged to 1
  EXPECT_EQ(pl.component_parent(2), 1);
  EXPECT_FALSE(pl.directly_joined(0, 2));
  // A sphere of radius 0.2 at p overlaps spheres 0 and 2 (centres 0.255 away,
  // radii sums 0.3) and clears every centre by more than 0.2 (rule (b)).
  const V p(0.05, 0.25, 0);
  // Fused to sphere 1: component 1 is joined to both 0 and 2.
  EXPECT_TRUE(pl.admissible(p, 0.2, 1, false));
  // Hinged to sphere 1: the new component is joined to component 1 only.
  EXPECT_FALSE(pl.admissible(p, 0.2, 1, true));
  // Fused to sphere 2 (component 2): component 0 is two hinges away.
  EXPECT_FALSE(pl.admissible(p, 0.2, 2, false));
  // Fused to the root (component 0): component 2 is two hinges away.
  EXPECT_FALSE(pl.admissible(p, 0.2, 0, false));
  // Small enough to clear both, it is admissible however attached.
  EXPECT_TRUE(pl.admissible(p, 0.15, 2, false));
  EXPECT_TRUE(pl.admissible(p, 0.15, 1, true));
}

TEST(Placement, AddChecksItsParent) {
  Placement pl(2.0, 4);
  EXPECT_THROW(pl.add(V(0, 0, 0), 0.1, 0, false), std::logic_error);
  pl.add_root(V(0, 0, 0), 0.1);
  EXPECT_THROW(pl.add_root(V(0, 0, 0), 0.1), std::logic_error);
  EXPECT_THROW(pl.add(V(0.1, 0, 0), 0.1, 3, false), std::logic_error);
}

}  // namespace
}  // namespace robozoo
