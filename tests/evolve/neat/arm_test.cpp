// The arms of an experiment: their names, regimes and generation-0 topologies, and the
// arm a run's configuration belongs to.
#include "evolve/neat/arm.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace robozoo {
namespace {

TEST(Arm, NamesRegimesAndStartsOfEveryArm) {
  for (int i = 0; i < kNumArms; ++i) {
    const Arm arm = static_cast<Arm>(i);
    EXPECT_EQ(arm_from_name(arm_name(arm)), arm);
    EXPECT_EQ(arm_of(arm_regime(arm), arm_initial_links(arm)), arm) << arm_name(arm);
  }
  EXPECT_EQ(arm_name(Arm::RecurrentZero), "recurrent-zero");
  EXPECT_EQ(arm_regime(Arm::RecurrentZero), Regime::Recurrent);
  EXPECT_EQ(arm_initial_links(Arm::RecurrentZero), InitialLinks::AllAllowedRecurrentZero);
  EXPECT_EQ(arm_initial_links(Arm::RecurrentSparse), InitialLinks::InputsToOutputs);
  EXPECT_EQ(arm_initial_links(Arm::Recurrent), InitialLinks::AllAllowed);
  EXPECT_EQ(arm_initial_links(Arm::FeedForward), InitialLinks::AllAllowed);
  EXPECT_EQ(arm_of(Regime::Recurrent, InitialLinks::AllAllowedRecurrentZero), Arm::RecurrentZero);
  EXPECT_EQ(arm_of(Regime::FeedForward, InitialLinks::AllAllowedRecurrentZero), Arm::FeedForward);
}

TEST(Arm, TheArmOfARunsConfiguration) {
  EXPECT_EQ(arm_of(Regime::Recurrent, InitialLinks::InputsToOutputs), Arm::RecurrentSparse);
  EXPECT_EQ(arm_of(Regime::Recurrent, InitialLinks::AllAllowed), Arm::Recurrent);
  EXPECT_EQ(arm_of(Regime::FeedForward, InitialLinks::InputsToOutputs), Arm::FeedForward);
  EXPECT_THROW(arm_from_name("sparse"), std::invalid_argument);
}

}  // namespace
}  // namespace robozoo
