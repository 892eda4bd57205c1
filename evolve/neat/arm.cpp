#include "evolve/neat/arm.hpp"

#include <stdexcept>

namespace robozoo {

std::string arm_name(Arm a) {
  switch (a) {
    case Arm::FeedForward: return "feedforward";
    case Arm::Recurrent: return "recurrent";
    case Arm::RecurrentSparse: return "recurrent-sparse";
    case Arm::RecurrentZero: return "recurrent-zero";
  }
  return "unknown";
}

Arm arm_from_name(const std::string& name) {
  for (int a = 0; a < kNumArms; ++a)
    if (arm_name(static_cast<Arm>(a)) == name) return static_cast<Arm>(a);
  throw std::invalid_argument("unknown arm '" + name +
                              "' (use feedforward, recurrent, recurrent-sparse, recurrent-zero)");
}

Regime arm_regime(Arm a) { return a == Arm::FeedForward ? Regime::FeedForward : Regime::Recurrent; }

InitialLinks arm_initial_links(Arm a) {
  switch (a) {
    case Arm::RecurrentSparse: return InitialLinks::InputsToOutputs;
    case Arm::RecurrentZero: return InitialLinks::AllAllowedRecurrentZero;
    case Arm::FeedForward:
    case Arm::Recurrent: break;
  }
  return NeatParams{}.initial_links;
}

Arm arm_of(Regime regime, InitialLinks initial_links) {
  if (regime == Regime::FeedForward) return Arm::FeedForward;
  switch (initial_links) {
    case InitialLinks::InputsToOutputs: return Arm::RecurrentSparse;
    case InitialLinks::AllAllowedRecurrentZero: return Arm::RecurrentZero;
    case InitialLinks::AllAllowed: break;
  }
  return Arm::Recurrent;
}

}  // namespace robozoo
