#include "study/analysis/measure/topology.hpp"

#include <gtest/gtest.h>

#include "tests/study/analysis/builders.hpp"

namespace robozoo {
namespace {

using testing::make_morphology;

TEST(Topology, SameTreeShapeWithOtherRadiiIsTheSameTopology) {
  // Root with a chain of two and a single leaf.
  const auto a = make_morphology({-1, 0, 1, 0}, {0.1, 0.2, 0.05, 0.3});
  const auto b = make_morphology({-1, 0, 1, 0}, {0.1, 0.45, 0.5, 0.06}, {false, true, false, false}, {1, 2, 4, 8});
  EXPECT_TRUE(same_topology(a, b));
  EXPECT_EQ(topology_code(a), "((())())");
}

TEST(Topology, SiblingOrderDoesNotMatter) {
  // The chain grown first or second: the same unordered tree.
  const auto a = make_morphology({-1, 0, 1, 0});
  const auto b = make_morphology({-1, 0, 0, 2});
  EXPECT_TRUE(same_topology(a, b));
}

TEST(Topology, AMovedBranchIsAnotherTopology) {
  // Sphere 3 hangs from the root in `a`, from sphere 2 (the end of the chain) in `b`.
  const auto a = make_morphology({-1, 0, 1, 0});
  const auto b = make_morphology({-1, 0, 1, 2});
  EXPECT_FALSE(same_topology(a, b));
  // Moved to sphere 1 instead: a fork under sphere 1.
  const auto c = make_morphology({-1, 0, 1, 1});
  EXPECT_FALSE(same_topology(a, c));
  EXPECT_FALSE(same_topology(b, c));
  EXPECT_EQ(topology_code(c), "((()()))");
  // Different sizes are never the same.
  EXPECT_FALSE(same_topology(a, make_morphology({-1, 0, 1})));
}

TEST(Topology, JointsCountOnlyWhenAsked) {
  const auto fused = make_morphology({-1, 0, 1}, {}, {false, false, false});
  const auto jointed = make_morphology({-1, 0, 1}, {}, {false, true, false});
  EXPECT_TRUE(same_topology(fused, jointed));
  TopologyOptions with_joints;
  with_joints.joints = true;
  EXPECT_FALSE(same_topology(fused, jointed, with_joints));
  EXPECT_EQ(topology_code(jointed, with_joints), "(j(()))");
}

TEST(Topology, MalformedTreesAreRefused) {
  EXPECT_THROW(topology_code(make_morphology({0, 0})), std::invalid_argument);      // root with a parent
  EXPECT_THROW(topology_code(make_morphology({-1, 2, 0})), std::invalid_argument);  // parent after child
  EXPECT_THROW(topology_code(make_morphology({-1, -1})), std::invalid_argument);    // two roots
  EXPECT_THROW(topology_code(make_morphology({})), std::invalid_argument);
}

}  // namespace
}  // namespace robozoo
