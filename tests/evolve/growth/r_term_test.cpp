// score_r_term (paper 2.4) on hand-built robot models.
#include <gtest/gtest.h>

#include "evolve/growth/growth.hpp"

namespace robozoo {
namespace {

// A robot with every part: a distance sensor, a joint, a neuron self-loop and a
// sensor -> neuron link.
Robot complete() {
  Robot r;
  r.spheres.resize(2);
  r.spheres[1].parent = 0;
  r.spheres[1].has_joint = true;
  r.joints = {Joint{}};
  r.joints[0].sphere = 1;
  r.neurons = {Neuron{1, 0.5, 0.0}};
  r.sensors = {Sensor{0, SensorType::Touch}, Sensor{1, SensorType::Distance}};
  r.w_sensor_neuron = Eigen::MatrixXd::Zero(2, 1);
  r.w_sensor_neuron(1, 0) = -0.9;
  r.w_neuron_neuron = Eigen::MatrixXd::Constant(1, 1, 2.0);
  return r;
}

double r_of(Robot r) {
  score_r_term(r);
  return r.r_term;
}

TEST(RTerm, AllPartsAndADistanceSensorEarnSimulation) {
  Robot r = complete();
  score_r_term(r);
  EXPECT_EQ(r.r_term, 15.0);
  EXPECT_TRUE(r.simulate);
}

TEST(RTerm, EachMissingPartCostsOneAndTheSimulation) {
  Robot no_link = complete();
  no_link.w_neuron_neuron.setZero();
  EXPECT_EQ(r_of(no_link), 4.0);

  Robot no_sensor_link = complete();
  no_sensor_link.w_sensor_neuron.setZero();
  EXPECT_EQ(r_of(no_sensor_link), 4.0);

  // No joint means no neuron, so no link of either kind: 1 + sensors.
  Robot no_joint = complete();
  no_joint.joints.clear();
  no_joint.neurons.clear();
  no_joint.w_sensor_neuron.resize(2, 0);
  no_joint.w_neuron_neuron.resize(0, 0);
  EXPECT_EQ(r_of(no_joint), 2.0);

  // No sensor: 1 + joint + neuron link.
  Robot no_sensor = complete();
  no_sensor.sensors.clear();
  no_sensor.w_sensor_neuron.resize(0, 1);
  EXPECT_EQ(r_of(no_sensor), 3.0);

  Robot bare;
  EXPECT_EQ(r_of(bare), 1.0);
  bare.sensors = {Sensor{0, SensorType::Distance}};
  EXPECT_EQ(r_of(bare), 2.0);  // a distance sensor alone is worth its +1 only
}

TEST(RTerm, TheBonusNeedsADistanceSensor) {
  Robot r = complete();
  r.sensors[1].type = SensorType::Time;
  score_r_term(r);
  EXPECT_EQ(r.r_term, 5.0);
  EXPECT_FALSE(r.simulate);
  r.sensors[0].type = SensorType::Distance;  // any sphere's distance sensor will do
  score_r_term(r);
  EXPECT_EQ(r.r_term, 15.0);
  EXPECT_TRUE(r.simulate);
}

TEST(RTerm, RescoringOverwrites) {
  Robot r = complete();
  score_r_term(r);
  r.w_sensor_neuron.setZero();
  score_r_term(r);
  EXPECT_EQ(r.r_term, 4.0);
  EXPECT_FALSE(r.simulate);
}

}  // namespace
}  // namespace robozoo
