#include "replay/compare/pose_compare.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace robozoo::replay {
namespace {

pose_t sample() {
  pose_t p{};
  p.utime = 1;
  p.run_id = "run";
  p.generation = 2;
  p.genome_id = 9;
  p.step = 120;
  p.sim_time = 1.2;
  p.num_bodies = 2;
  p.body_position = {{0.1, 0.2, 0.3}, {0.4, 0.5, 0.6}};
  p.body_quaternion = {{1, 0, 0, 0}, {0.5, 0.5, 0.5, 0.5}};
  p.num_spheres = 3;
  p.sphere_center = {{0, 0, 0.1}, {0.2, 0, 0.1}, {0.4, 0, 0.1}};
  p.num_neurons = 1;
  p.neuron_output = {0.3};
  p.num_sensors = 2;
  p.sensor_value = {0.9, 0.0};
  return p;
}

TEST(PoseCompare, IdenticalButForUtimeIsEqual) {
  pose_t a = sample(), b = sample();
  b.utime = 12345;
  ValueComparer c;
  EXPECT_TRUE(compare_pose(a, b, c));
  EXPECT_EQ(c.values_compared(), 5 + 1 + 14 + 1 + 9 + 1 + 1 + 1 + 2);
}

TEST(PoseCompare, OneFlippedBitNamesStepBodyAndField) {
  pose_t a = sample(), b = sample();
  a.body_position[1][2] = std::nextafter(a.body_position[1][2], 1.0);
  ValueComparer c;
  EXPECT_FALSE(compare_pose(a, b, c));
  ASSERT_EQ(c.mismatch_count(), 1);
  const Mismatch& m = c.mismatches()[0];
  EXPECT_EQ(m.what, "pose");
  EXPECT_EQ(m.step, 120);
  EXPECT_EQ(m.element, "body 1");
  EXPECT_EQ(m.field, "body_position[1][2]");
  EXPECT_NE(m.logged, m.recomputed);
}

TEST(PoseCompare, SpheresNeuronsSensorsAndCounts) {
  pose_t a = sample(), b = sample();
  a.sphere_center[2][0] = 0.5;
  a.sensor_value[1] = 0.25;
  a.num_neurons = 0;
  a.neuron_output.clear();
  ValueComparer c;
  EXPECT_FALSE(compare_pose(a, b, c));
  std::vector<std::string> got;
  for (const auto& m : c.mismatches()) got.push_back(m.element + ":" + m.field);
  EXPECT_EQ(got,
            (std::vector<std::string>{"sphere 2:sphere_center[2][0]", ":num_neurons", "sensor 1:sensor_value[1]"}));
}

}  // namespace
}  // namespace robozoo::replay
