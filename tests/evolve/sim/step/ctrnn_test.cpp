#include "evolve/sim/step/ctrnn.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "evolve/sim/robots/robot_builder.hpp"

namespace robozoo {
namespace {

// A chain root - jointed sphere(s); each jointed sphere carries one motor neuron.
Robot neurons(int n, double tau0, double omega0, double tau1 = 1.0, double omega1 = 0.0, uint8_t root_sensors = 0) {
  RobotBuilder b;
  int p = b.add_root({0, 0, 0}, 0.2, 1.0, root_sensors);
  p = b.add_jointed(p, {0.2, 0, 0}, 0.2, {0, 1, 0}, 1.0, tau0, omega0);
  if (n > 1) b.add_jointed(p, {0.4, 0, 0}, 0.2, {0, 1, 0}, 1.0, tau1, omega1);
  return b.build();
}

TEST(Ctrnn, ResetSetsStatesToZeroAndOutputsToTanhOfBias) {
  const Robot r = neurons(2, 0.5, 0.7, 1.0, -0.3);
  Ctrnn c(r);
  EXPECT_EQ(c.size(), 2);
  EXPECT_DOUBLE_EQ(c.state()[0], 0.0);
  EXPECT_DOUBLE_EQ(c.outputs()[0], std::tanh(0.7));
  EXPECT_DOUBLE_EQ(c.outputs()[1], std::tanh(-0.3));
}

TEST(Ctrnn, OneNeuronWithoutInputsDecaysByEuler) {
  // tau dy/dt = -y: with no links y stays 0, so the output stays tanh(omega).
  const Robot r = neurons(1, 0.5, 0.4);
  Ctrnn c(r);
  c.step(nullptr, 0.01);
  EXPECT_DOUBLE_EQ(c.state()[0], 0.0);
  EXPECT_DOUBLE_EQ(c.outputs()[0], std::tanh(0.4));
}

TEST(Ctrnn, SelfLoopStepByHand) {
  Robot r = neurons(1, 0.5, 0.4);
  r.w_neuron_neuron(0, 0) = 2.0;
  Ctrnn c(r);
  const double dt = 0.01;
  // Step 1: y = 0 + dt/tau * (-0 + 2 tanh(0 + 0.4)).
  const double y1 = dt / 0.5 * (2.0 * std::tanh(0.4));
  c.step(nullptr, dt);
  EXPECT_DOUBLE_EQ(c.state()[0], y1);
  EXPECT_DOUBLE_EQ(c.outputs()[0], std::tanh(y1 + 0.4));
  // Step 2 reads step 1's output.
  const double y2 = y1 + dt / 0.5 * (-y1 + 2.0 * std::tanh(y1 + 0.4));
  c.step(nullptr, dt);
  EXPECT_DOUBLE_EQ(c.state()[0], y2);
  c.reset();
  EXPECT_DOUBLE_EQ(c.state()[0], 0.0);
}

TEST(Ctrnn, TwoNeuronsReadTheSameInstantAndUseWFromJToI) {
  Robot r = neurons(2, 0.2, 0.5, 0.4, -1.0);
  r.w_neuron_neuron(0, 1) = 1.5;   // from 0 to 1
  r.w_neuron_neuron(1, 0) = -2.0;  // from 1 to 0
  Ctrnn c(r);
  const double dt = 0.01;
  const double o0 = std::tanh(0.5), o1 = std::tanh(-1.0);
  const double y0 = dt / 0.2 * (-2.0 * o1);
  const double y1 = dt / 0.4 * (1.5 * o0);  // reads neuron 0's output before its update
  c.step(nullptr, dt);
  EXPECT_DOUBLE_EQ(c.state()[0], y0);
  EXPECT_DOUBLE_EQ(c.state()[1], y1);
  EXPECT_DOUBLE_EQ(c.outputs()[1], std::tanh(y1 - 1.0));
}

TEST(Ctrnn, SensorInputEntersThroughWSensorNeuron) {
  Robot r = neurons(1, 0.1, 0.0, 1.0, 0.0, kSensorDistance | kSensorTime);
  ASSERT_EQ(r.sensors.size(), 2u);
  r.w_sensor_neuron(0, 0) = 0.5;
  r.w_sensor_neuron(1, 0) = -3.0;
  Ctrnn c(r);
  const double s[2] = {0.8, 0.25};
  c.step(s, 0.02);
  const double y = 0.02 / 0.1 * (0.5 * 0.8 - 3.0 * 0.25);
  EXPECT_DOUBLE_EQ(c.state()[0], y);
  EXPECT_DOUBLE_EQ(c.outputs()[0], std::tanh(y));
  EXPECT_GT(c.outputs()[0], -1.0);
}

TEST(Ctrnn, RejectsMismatchedWeightsAndNonPositiveTau) {
  Robot r = neurons(1, 0.5, 0.0);
  r.w_neuron_neuron.resize(2, 2);
  EXPECT_THROW(Ctrnn{r}, std::invalid_argument);
  Robot q = neurons(1, 0.5, 0.0);
  q.neurons[0].tau = 0.0;
  EXPECT_THROW(Ctrnn{q}, std::invalid_argument);
}

}  // namespace
}  // namespace robozoo
