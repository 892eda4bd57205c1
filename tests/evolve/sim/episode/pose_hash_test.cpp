#include <gtest/gtest.h>

#include <cmath>

#include "evolve/sim/episode/simulation.hpp"

namespace robozoo {
namespace {

SimState state() {
  SimState s;
  s.body_position = {{0.1, 0.2, 0.3}, {1, 2, 3}};
  s.body_quaternion = {{1, 0, 0, 0}, {0.5, 0.5, 0.5, 0.5}};
  s.sphere_center = {{0, 0, 0}};
  return s;
}

TEST(PoseHash, EqualPosesHashEqual) { EXPECT_EQ(pose_hash(state()), pose_hash(state())); }

TEST(PoseHash, OneBitOfAnyPositionOrQuaternionChangesIt) {
  const uint64_t h = pose_hash(state());
  SimState s = state();
  s.body_position[1].y() = std::nextafter(2.0, 3.0);
  EXPECT_NE(pose_hash(s), h);
  s = state();
  s.body_quaternion[0][3] = -0.0;  // exact bits: -0 differs from +0
  EXPECT_NE(pose_hash(s), h);
  s = state();
  std::swap(s.body_position[0], s.body_position[1]);  // order matters
  EXPECT_NE(pose_hash(s), h);
}

TEST(PoseHash, CoversBodiesOnly) {
  const uint64_t h = pose_hash(state());
  SimState s = state();
  s.sphere_center[0].x() = 5;
  s.time = 3;
  s.neuron_output = {0.5};
  EXPECT_EQ(pose_hash(s), h);
}

}  // namespace
}  // namespace robozoo
