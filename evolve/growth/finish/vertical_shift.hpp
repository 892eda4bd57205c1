#pragma once
// Growth step 7 (paper 3; docs/method.md section 2): rest the robot on the ground.
#include "evolve/growth/robot.hpp"

namespace robozoo {

/// Translates every centre vertically so the largest sphere (ties: first in
/// growth order) has its bottom at z = 0, i.e. dz = radius - center.z of that
/// sphere; adds dz to robot.vertical_shift. All centres share one height after
/// growth, so no other sphere reaches below z = 0. Returns dz (m). A robot
/// without spheres is left alone (dz = 0).
double rest_on_ground(Robot& robot);

}  // namespace robozoo
