#include "replay/compare/value_compare.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace robozoo::replay {
namespace {

TEST(ValueError, RelativeAboveOneAbsoluteBelow) {
  EXPECT_EQ(value_error(2.0, 2.0), 0.0);
  EXPECT_DOUBLE_EQ(value_error(100.0, 101.0), 1.0 / 101.0);
  EXPECT_DOUBLE_EQ(value_error(1e-3, 2e-3), 1e-3);
  EXPECT_EQ(value_error(0.0, -0.0), 0.0);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(value_error(nan, nan), 0.0);
  EXPECT_TRUE(std::isinf(value_error(nan, 1.0)));
  EXPECT_TRUE(std::isinf(value_error(std::numeric_limits<double>::infinity(), 1.0)));
}

TEST(ValueComparer, ExactByDefaultDownToTheLastBit) {
  ValueComparer c;
  const double x = 0.1;
  const double y = std::nextafter(x, 1.0);
  EXPECT_TRUE(c.real({"a"}, x, x));
  EXPECT_FALSE(c.real({"body_position[%d][%d]", 2, 1, "body"}, x, y));
  EXPECT_FALSE(c.real({"b"}, 0.0, -0.0));  // bit for bit: the sign of zero counts
  EXPECT_EQ(c.mismatch_count(), 2);
  EXPECT_EQ(c.values_compared(), 3);
  ASSERT_EQ(c.mismatches().size(), 2u);
  const Mismatch& m = c.mismatches()[0];
  EXPECT_EQ(m.field, "body_position[2][1]");
  EXPECT_EQ(m.element, "body 2");
  EXPECT_EQ(m.logged, exact_text(x));
  EXPECT_EQ(m.recomputed, exact_text(y));
  EXPECT_EQ(std::stod(m.recomputed), y);  // the text reads back to the same bits
  EXPECT_GT(c.max_error(), 0.0);
  EXPECT_LT(c.max_error(), 1e-15);
}

TEST(ValueComparer, ToleranceAcceptsSmallErrorsButStillMeasuresThem) {
  ValueComparer c(1e-9);
  EXPECT_TRUE(c.real({"x"}, 1.0, 1.0 + 1e-12));
  EXPECT_FALSE(c.real({"y"}, 1.0, 1.0 + 1e-6));
  EXPECT_EQ(c.mismatch_count(), 1);
  EXPECT_NEAR(c.max_error(), 1e-6 / (1.0 + 1e-6), 1e-15);
  EXPECT_THROW(ValueComparer(-1.0), std::invalid_argument);
  EXPECT_THROW(ValueComparer(std::nan("")), std::invalid_argument);
}

TEST(ValueComparer, ExactFieldsIgnoreTheTolerance) {
  ValueComparer c(0.5);
  EXPECT_FALSE(c.integer({"num_bodies"}, 3, 4));
  EXPECT_FALSE(c.text({"run_id"}, "a", "b"));
  EXPECT_TRUE(c.integer({"step"}, 7, 7));
  ASSERT_EQ(c.mismatches().size(), 2u);
  EXPECT_TRUE(std::isinf(c.mismatches()[0].error));
  EXPECT_EQ(c.mismatches()[1].logged, "\"a\"");
  EXPECT_EQ(c.max_error(), 0.0);  // only real values count towards the max error
}

TEST(ValueComparer, KeepsTheFirstDetailsAndCountsAll) {
  ValueComparer c(0.0, 3);
  c.set_context("pose", 40);
  for (int i = 0; i < 10; ++i) c.real({"neuron_output[%d]", i, -1, "neuron"}, i, i + 0.5);
  EXPECT_EQ(c.mismatch_count(), 10);
  ASSERT_EQ(c.mismatches().size(), 3u);
  EXPECT_EQ(c.mismatches()[2].field, "neuron_output[2]");
  EXPECT_EQ(c.mismatches()[2].what, "pose");
  EXPECT_EQ(c.mismatches()[2].step, 40);
  c.note("step", "400", "the re-simulation ends at step 380");
  EXPECT_EQ(c.mismatch_count(), 11);
  EXPECT_FALSE(c.ok());
}

}  // namespace
}  // namespace robozoo::replay
