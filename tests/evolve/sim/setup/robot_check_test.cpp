#include "evolve/sim/setup/robot_check.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "evolve/sim/robots/robot_builder.hpp"

namespace robozoo {
namespace {

Robot two_bodies() {
  RobotBuilder b;
  const int a = b.add_root({0, 0, 0}, 0.2, 1.0, kSensorDistance);
  const int j = b.add_jointed(a, {0.2, 0, 0}, 0.2, {0, 1, 0}, 0.5, 0.5, 0.0, 1.0, kSensorProprio);
  b.add_fused(j, {0.4, 0, 0}, 0.2);
  return b.build();
}

std::string message_of(const Robot& r) {
  try {
    check_robot(r);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(RobotCheck, AcceptsABuiltRobot) { EXPECT_NO_THROW(check_robot(two_bodies())); }

TEST(RobotCheck, NamesTheFirstProblem) {
  Robot r = two_bodies();
  r.spheres[1].radius = -1;
  EXPECT_NE(message_of(r).find("sphere 1"), std::string::npos);

  r = two_bodies();
  r.joints[0].axis = {0, 2, 0};
  EXPECT_NE(message_of(r).find("unit axis"), std::string::npos);

  r = two_bodies();
  r.joints.clear();
  EXPECT_NE(message_of(r).find("joint"), std::string::npos);

  r = two_bodies();
  r.w_neuron_neuron.resize(0, 0);
  EXPECT_NE(message_of(r).find("w_neuron_neuron"), std::string::npos);

  r = two_bodies();
  r.sensors[1].sphere = 0;  // the proprio sensor moved to the unjointed root
  EXPECT_NE(message_of(r).find("proprioceptive"), std::string::npos);

  r = two_bodies();
  r.spheres[2].body = 0;  // fused to its parent but in another body
  EXPECT_NE(message_of(r).find("fused"), std::string::npos);

  r = two_bodies();
  r.neurons[0].tau = 0;
  EXPECT_NE(message_of(r).find("tau"), std::string::npos);

  r = Robot{};
  EXPECT_NE(message_of(r).find("no spheres"), std::string::npos);
}

}  // namespace
}  // namespace robozoo
