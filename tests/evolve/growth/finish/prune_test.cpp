#include "evolve/growth/finish/prune.hpp"

#include <gtest/gtest.h>

namespace robozoo {
namespace {

// root 0 -- 1 (jointed, has child 2) -- 2 (jointed leaf); root -- 3 (fused leaf);
// root -- 4 (jointed leaf).
GrownBody tree() {
  GrownBody b;
  auto add = [&](int parent, bool joint, uint8_t sensors) {
    Sphere s;
    s.index = static_cast<int>(b.spheres.size());
    s.parent = parent;
    s.has_joint = joint;
    s.joint_axis = joint ? Eigen::Vector3d(0, 1, 0) : Eigen::Vector3d::Zero();
    s.joint_range = joint ? 0.5 : 0.0;
    s.sensors = sensors;
    if (parent >= 0) b.spheres[parent].num_children++;
    b.spheres.push_back(s);
    b.motors.push_back(Neuron{s.index, joint ? 0.3 : 0.0, joint ? 1.0 : 0.0});
  };
  add(-1, false, kSensorTouch);
  add(0, true, kSensorProprio | kSensorDistance);
  add(1, true, kSensorProprio | kSensorTime);
  add(0, false, kSensorTouch);
  add(0, true, kSensorProprio);
  return b;
}

TEST(Prune, LeafJointsBecomeRigidOthersStay) {
  GrownBody b = tree();
  EXPECT_EQ(prune_leaf_joints(b), 2);
  // Sphere 1 has a child: keeps joint, motor and proprioception.
  EXPECT_TRUE(b.spheres[1].has_joint);
  EXPECT_FALSE(b.spheres[1].joint_pruned);
  EXPECT_EQ(b.spheres[1].sensors, kSensorProprio | kSensorDistance);
  EXPECT_EQ(b.motors[1].tau, 0.3);
  // Leaves 2 and 4 lose joint, range, motor and proprioception.
  for (int i : {2, 4}) {
    const Sphere& s = b.spheres[i];
    EXPECT_FALSE(s.has_joint);
    EXPECT_TRUE(s.joint_pruned);
    EXPECT_EQ(s.joint_axis, Eigen::Vector3d::Zero());
    EXPECT_EQ(s.joint_range, 0.0);
    EXPECT_EQ(s.sensors & kSensorProprio, 0);
    EXPECT_EQ(b.motors[i].tau, 0.0);
  }
  EXPECT_EQ(b.spheres[2].sensors, kSensorTime);
  // A fused leaf is untouched.
  EXPECT_FALSE(b.spheres[3].joint_pruned);
  EXPECT_EQ(b.spheres[3].sensors, kSensorTouch);
  // A second pass finds nothing: pruning makes no new leaves.
  EXPECT_EQ(prune_leaf_joints(b), 0);
}

}  // namespace
}  // namespace robozoo
