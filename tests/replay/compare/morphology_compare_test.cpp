#include "replay/compare/morphology_compare.hpp"

#include <gtest/gtest.h>

namespace robozoo::replay {
namespace {

morphology_t sample() {
  morphology_t m{};
  m.utime = 5;
  m.run_id = "run";
  m.generation = 3;
  m.genome_id = 42;
  m.num_spheres = 3;
  for (int s = 0; s < 3; ++s) {
    sphere_t x{};
    x.index = s;
    x.parent = s - 1;
    x.center[0] = 0.1 * s;
    x.center[2] = 0.2;
    x.radius = 0.1 + 0.01 * s;
    x.density = 1.5;
    x.body = s == 2 ? 1 : 0;
    x.has_joint = s == 2;
    if (s == 2) {
      x.joint_axis[1] = 1.0;
      x.joint_range = 0.7;
      x.motor_neuron = 0;
    } else {
      x.motor_neuron = -1;
    }
    x.sensors = s == 0 ? 1 : 0;
    m.spheres.push_back(x);
  }
  m.num_bodies = 2;
  m.num_neurons = 1;
  m.tau = {0.4};
  m.omega = {0.2};
  m.num_sensors = 2;
  m.sensor_sphere = {0, 2};
  m.sensor_type = {0, 2};
  m.w_sensor_neuron = {{0.5}, {-0.25}};
  m.w_neuron_neuron = {{0.75}};
  m.r_term = 15;
  return m;
}

TEST(MorphologyCompare, IdenticalButForUtimeIsEqual) {
  morphology_t a = sample(), b = sample();
  b.utime = 99;
  ValueComparer c;
  EXPECT_TRUE(compare_morphology(a, b, c));
  EXPECT_EQ(c.mismatch_count(), 0);
  EXPECT_GT(c.values_compared(), 40);
}

TEST(MorphologyCompare, NamesTheSphereAndFieldOfAChangedRadius) {
  morphology_t a = sample(), b = sample();
  a.spheres[2].radius = 0.125;
  ValueComparer c;
  EXPECT_FALSE(compare_morphology(a, b, c));
  ASSERT_EQ(c.mismatch_count(), 1);
  const Mismatch& m = c.mismatches()[0];
  EXPECT_EQ(m.what, "morphology");
  EXPECT_EQ(m.field, "spheres[2].radius");
  EXPECT_EQ(m.element, "sphere 2");
  EXPECT_EQ(m.logged, "0.125");
  EXPECT_EQ(std::stod(m.recomputed), b.spheres[2].radius);
}

TEST(MorphologyCompare, NamesWeightsTypesAndScalars) {
  morphology_t a = sample(), b = sample();
  a.w_sensor_neuron[1][0] = 0.0;
  a.sensor_type[0] = 3;
  a.r_term = 16;
  a.genome_id = 7;
  ValueComparer c;
  EXPECT_FALSE(compare_morphology(a, b, c));
  std::vector<std::string> fields;
  for (const auto& m : c.mismatches()) fields.push_back(m.field);
  EXPECT_EQ(fields, (std::vector<std::string>{"genome_id", "sensor_type[0]", "w_sensor_neuron[1][0]", "r_term"}));
}

TEST(MorphologyCompare, DifferentCountsAreReportedWithoutReadingPastArrays) {
  morphology_t a = sample(), b = sample();
  a.num_spheres = 2;
  a.spheres.pop_back();
  a.num_neurons = 0;
  a.tau.clear();
  a.omega.clear();
  a.w_sensor_neuron = {{}, {}};
  a.w_neuron_neuron.clear();
  ValueComparer c;
  EXPECT_FALSE(compare_morphology(a, b, c));
  std::vector<std::string> fields;
  for (const auto& m : c.mismatches()) fields.push_back(m.field);
  EXPECT_EQ(fields, (std::vector<std::string>{"num_spheres", "num_neurons"}));
  EXPECT_EQ(c.mismatches()[0].logged, "2");
  EXPECT_EQ(c.mismatches()[0].recomputed, "3");
}

}  // namespace
}  // namespace robozoo::replay
