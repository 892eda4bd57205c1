#include "study/analysis/measure/initial_robots.hpp"

#include <gtest/gtest.h>

namespace robozoo {
namespace {

TEST(InitialRobots, GrowsEachArmsStartAndCountsConsistently) {
  RunConfig ff;
  RunConfig rec;
  rec.regime = Regime::Recurrent;
  const InitialRobotShares a = initial_robot_shares(ff, 60, 3);
  const InitialRobotShares b = initial_robot_shares(rec, 60, 3);
  EXPECT_EQ(a.genomes, 60);
  EXPECT_EQ(a.mean_links, 99.0);
  EXPECT_EQ(b.mean_links, 209.0);
  for (const auto& s : {a, b}) {
    EXPECT_LE(s.joint_and_distance, s.with_joint);
    EXPECT_LE(s.with_joint, s.beyond_root);        // a joint needs a second sphere
    EXPECT_LE(s.simulated, s.joint_and_distance);  // simulation needs a joint and a distance sensor
    EXPECT_LE(s.beyond_root, s.genomes);
    EXPECT_GE(s.mean_spheres, 1.0);
  }
  // Deterministic in the seed; the sparse recurrent start grows what the control's does
  // (same weights on the same 99 links).
  const InitialRobotShares again = initial_robot_shares(rec, 60, 3);
  EXPECT_EQ(again.beyond_root, b.beyond_root);
  EXPECT_EQ(again.mean_spheres, b.mean_spheres);
  RunConfig sparse = rec;
  sparse.neat.initial_links = InitialLinks::InputsToOutputs;
  const InitialRobotShares c = initial_robot_shares(sparse, 60, 3);
  EXPECT_EQ(c.beyond_root, a.beyond_root);
  EXPECT_EQ(c.mean_spheres, a.mean_spheres);
}

}  // namespace
}  // namespace robozoo
