#include "evolve/sim/episode/outcome.hpp"

#include <gtest/gtest.h>

#include <set>
#include <stdexcept>

namespace robozoo {
namespace {

TEST(Outcome, CodesAreTheLogFormatsAndNamesAreDistinct) {
  EXPECT_EQ(static_cast<int>(Outcome::NotSimulated), 0);
  EXPECT_EQ(static_cast<int>(Outcome::AccelFault), 3);
  EXPECT_EQ(static_cast<int>(Outcome::RollingSpin), 5);
  std::set<std::string> names;
  for (int o = 0; o < kNumOutcomes; ++o) names.insert(outcome_name(static_cast<Outcome>(o)));
  EXPECT_EQ(names.size(), static_cast<size_t>(kNumOutcomes));
  EXPECT_EQ(outcome_name(Outcome::RollingContact), "rolling_contact");
  EXPECT_THROW(outcome_name(static_cast<Outcome>(17)), std::invalid_argument);
}

}  // namespace
}  // namespace robozoo
