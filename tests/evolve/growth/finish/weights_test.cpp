#include "evolve/growth/finish/weights.hpp"

#include <gtest/gtest.h>

#include "evolve/growth/growth.hpp"
#include "tests/evolve/growth/cppn_builders.hpp"

namespace robozoo {
namespace {

using testing::ssig;

// Three spheres on the x axis; neurons on spheres 1 and 2; a touch sensor on
// sphere 0 and a time sensor on sphere 2.
Robot model() {
  Robot r;
  for (int i = 0; i < 3; ++i) {
    Sphere s;
    s.index = i;
    s.center = Eigen::Vector3d(0.2 * i, 0.0, 0.0);
    r.spheres.push_back(s);
  }
  r.neurons = {Neuron{1, 0.5, 0}, Neuron{2, 0.5, 0}};
  r.sensors = {Sensor{0, SensorType::Touch}, Sensor{2, SensorType::Time}};
  return r;
}

TEST(Weights, MidpointQueriesWithTheSensorsOneHot) {
  // w = ssig(5 x - 1 + 2 s_touch + 0.5 r_parent): r_parent is 0 for weight queries.
  Genome g = testing::bare_robot_genome();
  testing::link(g, kInX, kOutWeight, 5.0);
  testing::link(g, kInBias, kOutWeight, -1.0);
  testing::link(g, kInSensorTouch, kOutWeight, 2.0);
  testing::link(g, kInRParent, kOutWeight, 0.5);
  Network net(g, robot_layout());
  CppnProbe probe(net, 1.0);
  GrowthParams p;
  Robot r = model();
  set_ctrnn_weights(r, probe, p);
  auto mid = [](int a, int b) { return (0.2 * a + 0.2 * b) / 2.0; };  // x of the midpoint
  auto w = [&](double sum) {  // HyperNEAT's rescaling: sign(o) (|o| - 0.2) / 0.8 * 3
    const double o = ssig(sum);
    if (!(std::abs(o) > 0.2)) return 0.0;
    return (o > 0 ? o - 0.2 : o + 0.2) / 0.8 * 3.0;
  };
  ASSERT_EQ(r.w_sensor_neuron.rows(), 2);
  ASSERT_EQ(r.w_sensor_neuron.cols(), 2);
  // touch (x = 0) -> neuron 0 (x = 0.2): midpoint 0.1, one-hot touch.
  EXPECT_DOUBLE_EQ(r.w_sensor_neuron(0, 0), w(5 * mid(0, 1) - 1 + 2));
  EXPECT_DOUBLE_EQ(r.w_sensor_neuron(0, 1), w(5 * mid(0, 2) - 1 + 2));
  // time sensor (x = 0.4) -> neuron 0 (x = 0.2): midpoint 0.3; ssig(0.5) = 0.245.
  EXPECT_DOUBLE_EQ(r.w_sensor_neuron(1, 0), w(5 * mid(2, 1) - 1));
  EXPECT_GT(r.w_sensor_neuron(1, 0), 0.0);
  // -> neuron 1 on the same sphere: midpoint 0.4, ssig(1) = 0.46.
  EXPECT_DOUBLE_EQ(r.w_sensor_neuron(1, 1), w(5 * mid(2, 2) - 1));
  // Neuron pairs, self-loops included: midpoints 0.2, 0.3, 0.4; no one-hot.
  // ssig(0) = 0 at the first: no link.
  EXPECT_EQ(r.w_neuron_neuron(0, 0), 0.0);
  EXPECT_DOUBLE_EQ(r.w_neuron_neuron(0, 1), w(5 * mid(1, 2) - 1));
  EXPECT_EQ(r.w_neuron_neuron(1, 0), r.w_neuron_neuron(0, 1));
  EXPECT_DOUBLE_EQ(r.w_neuron_neuron(1, 1), w(5 * mid(2, 2) - 1));
}

TEST(Weights, ThresholdIsStrict) {
  for (WeightMapping m : {WeightMapping::Rescaled, WeightMapping::Proportional}) {
    GrowthParams p;
    p.weight_mapping = m;
    EXPECT_EQ(expressed_weight(0.2, p), 0.0);
    EXPECT_EQ(expressed_weight(-0.2, p), 0.0);
    EXPECT_EQ(expressed_weight(0.19, p), 0.0);
    EXPECT_EQ(expressed_weight(0.0, p), 0.0);
    EXPECT_DOUBLE_EQ(expressed_weight(-1.0, p), -3.0) << "w = -1 gives -weight_max either way";
    EXPECT_DOUBLE_EQ(expressed_weight(1.0, p), 3.0);
  }
}

TEST(Weights, RescaledMappingStartsAtZeroAtTheThresholdAsHyperNeatDoes) {
  const GrowthParams p;  // the default: rescaled, threshold 0.2, weight_max 3
  ASSERT_EQ(p.weight_mapping, WeightMapping::Rescaled);
  EXPECT_EQ(expressed_weight(0.21, p), (0.21 - 0.2) / (1 - 0.2) * 3.0);
  EXPECT_EQ(expressed_weight(-0.21, p), (-0.21 + 0.2) / (1 - 0.2) * 3.0);
  EXPECT_DOUBLE_EQ(expressed_weight(0.6, p), 1.5);
  EXPECT_DOUBLE_EQ(expressed_weight(-0.6, p), -1.5);
  // Continuous at the threshold: just above it the weight is close to 0.
  EXPECT_LT(expressed_weight(0.2 + 1e-12, p), 1e-10);
  EXPECT_GT(expressed_weight(0.2 + 1e-12, p), 0.0);
  // Odd, and increasing in w.
  for (double w = 0.25; w < 1.0; w += 0.05) {
    EXPECT_DOUBLE_EQ(expressed_weight(-w, p), -expressed_weight(w, p));
    EXPECT_LT(expressed_weight(w, p), expressed_weight(w + 0.05, p));
  }
}

TEST(Weights, ProportionalMappingIsRobozoosEarlierOne) {
  GrowthParams p;
  p.weight_mapping = WeightMapping::Proportional;
  EXPECT_DOUBLE_EQ(expressed_weight(0.21, p), 0.63) << "jumps from 0 to 0.6 at the threshold";
  EXPECT_DOUBLE_EQ(expressed_weight(-0.6, p), -1.8);
}

TEST(Weights, RescaledMappingNeedsAThresholdBelowOne) {
  GrowthParams p;
  p.weight_threshold = 1.0;
  EXPECT_THROW(validate_growth_params(p), std::invalid_argument);
  p.weight_mapping = WeightMapping::Proportional;
  EXPECT_NO_THROW(validate_growth_params(p));
}

TEST(Weights, NoNeuronsNoWeights) {
  Genome g = testing::bare_robot_genome();
  testing::constant(g, kOutWeight, 0.9);
  Network net(g, robot_layout());
  CppnProbe probe(net, 1.0);
  Robot r = model();
  r.neurons.clear();
  set_ctrnn_weights(r, probe, {});
  EXPECT_EQ(r.w_sensor_neuron.rows(), 2);
  EXPECT_EQ(r.w_sensor_neuron.cols(), 0);
  EXPECT_EQ(r.w_neuron_neuron.size(), 0);
  EXPECT_EQ(probe.count(), 0);
}

}  // namespace
}  // namespace robozoo
