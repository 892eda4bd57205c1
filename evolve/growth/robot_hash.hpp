#pragma once
// A stable 64-bit hash of a whole Robot model (exact bits of every number), so
// that determinism tests and replay can compare grown robots cheaply.
#include <cstdint>

#include "evolve/growth/robot.hpp"

namespace robozoo {

uint64_t robot_hash(const Robot& robot);

}  // namespace robozoo
