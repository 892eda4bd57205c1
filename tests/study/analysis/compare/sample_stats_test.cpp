#include "study/analysis/compare/sample_stats.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace robozoo {
namespace {

TEST(SampleStats, MeanSdAndStandardError) {
  // {2, 4, 4, 4, 5, 5, 7, 9}: mean 5, sum of squares 32, sd = sqrt(32 / 7), se = sd / sqrt(8).
  const SampleStats s = describe({2, 4, 4, 4, 5, 5, 7, 9});
  EXPECT_EQ(s.n, 8u);
  EXPECT_DOUBLE_EQ(s.mean, 5.0);
  EXPECT_NEAR(s.sd, std::sqrt(32.0 / 7.0), 1e-15);
  EXPECT_NEAR(s.se, std::sqrt(32.0 / 7.0) / std::sqrt(8.0), 1e-15);
}

TEST(SampleStats, SmallSamples) {
  EXPECT_TRUE(std::isnan(describe({}).mean));
  const SampleStats one = describe({3.5});
  EXPECT_EQ(one.mean, 3.5);
  EXPECT_EQ(one.se, 0.0);
  EXPECT_THROW(describe({1.0, std::nan("")}), std::invalid_argument);
}

}  // namespace
}  // namespace robozoo
