#include "evolve/growth/body/cppn_probe.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

#include "evolve/growth/growth.hpp"
#include "tests/evolve/growth/cppn_builders.hpp"

namespace robozoo {
namespace {

// Linear outputs that copy inputs: out[i] = in[i] for i < 9; out[10] = 1e308 x.
Genome echo_genome() {
  Genome g = testing::bare_robot_genome();
  for (auto& n : g.nodes)
    if (n.kind == NodeKind::Output) n.activation = Activation::Linear;
  for (int i = 0; i < 9; ++i) testing::link(g, i, i, 1.0);
  testing::link(g, kInX, kOutWeight, 1e308);
  return g;
}

TEST(CppnProbe, RoutesEveryInput) {
  Network net(echo_genome(), robot_layout());
  CppnProbe probe(net, 0.75);
  CppnOutputs out;
  const SensorType touch = SensorType::Touch;
  probe.query(Eigen::Vector3d(0.5, -0.25, 0.125), 0.4, &touch, out);
  const double want[9] = {0.5, -0.25, 0.125, 0.4, 0.75, 0, 1, 0, 0};
  for (int i = 0; i < 9; ++i) EXPECT_EQ(out[i], want[i]) << i;
  // The one-hot is reset for the next query.
  probe.query(Eigen::Vector3d(0, 0, 0), 0.1, out);
  for (int i = 5; i < 9; ++i) EXPECT_EQ(out[i], 0.0) << i;
  const SensorType time = SensorType::Time;
  probe.query(Eigen::Vector3d(0, 0, 0), 0.0, &time, out);
  EXPECT_EQ(out[kInSensorTime], 1.0);
  EXPECT_EQ(out[kInSensorTouch], 0.0);
  EXPECT_EQ(probe.count(), 3);
}

TEST(CppnProbe, NonFiniteOutputsReadAsZero) {
  Network net(echo_genome(), robot_layout());
  CppnProbe probe(net, 1.0);
  CppnOutputs out;
  probe.query(Eigen::Vector3d(10, 0, 0), 0.1, out);  // 1e308 * 10 overflows
  EXPECT_EQ(out[kOutWeight], 0.0);
  EXPECT_EQ(out[0], 10.0);
}

TEST(CppnProbe, NeedsTheRobotLayout) {
  GenomeLayout l;
  l.num_inputs = 3;
  l.bias_input = 2;
  l.num_outputs = 11;
  Genome g;
  for (int i = 0; i < 3; ++i)
    g.nodes.push_back({i, i == 2 ? NodeKind::Bias : NodeKind::Input, Activation::Linear, 0.0});
  for (int o = 0; o < 11; ++o) g.nodes.push_back({3 + o, NodeKind::Output, Activation::SignedSigmoid, 1.0});
  Network net(g, l);
  EXPECT_THROW(CppnProbe(net, 1.0), std::invalid_argument);
}

}  // namespace
}  // namespace robozoo
