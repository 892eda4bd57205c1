#include "study/experiment/progress_estimate.hpp"

#include <gtest/gtest.h>

namespace robozoo {
namespace {

TEST(ProgressEstimate, RemainingTimeFromTheTimeSpentPerGeneration) {
  // 30 of 120 generations in 600 s: 20 s each, 90 left.
  const ProgressEstimate e = estimate_progress({120, 30, 600.0});
  EXPECT_TRUE(e.known);
  EXPECT_DOUBLE_EQ(e.fraction, 0.25);
  EXPECT_DOUBLE_EQ(e.remaining_seconds, 1800.0);
}

TEST(ProgressEstimate, UnknownBeforeTheFirstGenerationDoneWhenFinished) {
  EXPECT_FALSE(estimate_progress({120, 0, 0.0}).known);
  const ProgressEstimate done = estimate_progress({120, 120, 5000.0});
  EXPECT_TRUE(done.known);
  EXPECT_DOUBLE_EQ(done.fraction, 1.0);
  EXPECT_DOUBLE_EQ(done.remaining_seconds, 0.0);
}

TEST(ProgressEstimate, GenerationsOfUnknownTimeCountAsDoneButNotTowardsTheRate) {
  // 60 of 120 done, 20 of them in 400 s (20 s each), 40 from results without a time:
  // half done, 60 left at 20 s.
  const ProgressEstimate e = estimate_progress({120, 60, 400.0, 40});
  EXPECT_TRUE(e.known);
  EXPECT_DOUBLE_EQ(e.fraction, 0.5);
  EXPECT_DOUBLE_EQ(e.remaining_seconds, 1200.0);
  // None timed: no estimate, however many are done.
  EXPECT_FALSE(estimate_progress({120, 60, 0.0, 60}).known);
}

TEST(ProgressEstimate, Durations) {
  EXPECT_EQ(format_duration(45.2), "45s");
  EXPECT_EQ(format_duration(725), "12m05s");
  EXPECT_EQ(format_duration(3 * 3600 + 7 * 60 + 20), "3h07m");
  EXPECT_EQ(format_duration(2 * 86400 + 4 * 3600), "2d04h");
  EXPECT_EQ(format_duration(-3), "0s");
}

TEST(ProgressEstimate, ClockShowsTheDateOnlyOnAnotherDay) {
  const std::time_t now = std::time(nullptr);
  EXPECT_EQ(format_clock(now, now).size(), 5u);               // "HH:MM"
  EXPECT_EQ(format_clock(now + 3 * 86400, now).size(), 16u);  // "YYYY-mm-dd HH:MM"
}

}  // namespace
}  // namespace robozoo
