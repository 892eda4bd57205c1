#pragma once
#include <cstdint>
#include <string>

namespace robozoo {

/// Outcome codes are part of the log format (cppn_genome_t.outcome): never renumber.
enum class Outcome : int8_t {
  NotSimulated = 0,    ///< the robot lacked a required part (r < 15)
  Completed = 1,       ///< ran all steps
  StoppedEarly = 2,    ///< every body at rest
  AccelFault = 3,      ///< linear or angular acceleration over threshold: d = 0
  RollingContact = 4,  ///< a sphere touched the ground for > 95 % of the steps: d = 0
  RollingSpin = 5,     ///< a body's mean angular velocity over threshold: d = 0
};
constexpr int kNumOutcomes = 6;
std::string outcome_name(Outcome o);

}  // namespace robozoo
