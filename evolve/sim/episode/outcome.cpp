#include "evolve/sim/episode/outcome.hpp"

#include <stdexcept>

namespace robozoo {

std::string outcome_name(Outcome o) {
  switch (o) {
    case Outcome::NotSimulated: return "not_simulated";
    case Outcome::Completed: return "completed";
    case Outcome::StoppedEarly: return "stopped_early";
    case Outcome::AccelFault: return "accel_fault";
    case Outcome::RollingContact: return "rolling_contact";
    case Outcome::RollingSpin: return "rolling_spin";
  }
  throw std::invalid_argument("outcome_name: unknown outcome code " + std::to_string(static_cast<int>(o)));
}

}  // namespace robozoo
