#include "runlog/progress_bar.hpp"

#include <gtest/gtest.h>

#include <sstream>

namespace robozoo {
namespace {

TEST(ProgressBar, TextShowsBarCountShareAndEstimate) {
  EXPECT_EQ(progress_text("checking", 1, 4, 2.0, 8), "checking [##......]  1/4   25%  2.0 s, ~6.0 s left");
  EXPECT_EQ(progress_text("checking", 4, 4, 90.0, 4), "checking [####]  4/4  100%  1m30s");
  EXPECT_EQ(progress_text("x", 0, 0, 0.0, 2), "x [##]  0/0  100%  0.0 s");
}

TEST(ProgressBar, RedrawsInPlaceAtMostAsOftenAsAsked) {
  std::ostringstream out;
  ProgressBar bar(out, "c", {10, 1.0});
  bar.update(1, 10, 0.0);
  bar.update(2, 10, 0.5);  // too soon: skipped
  bar.update(3, 10, 1.2);
  bar.update(10, 10, 1.3);  // the last one always
  EXPECT_EQ(bar.redraws(), 3);
  const std::string s = out.str();
  EXPECT_EQ(s.find('\n'), std::string::npos);
  EXPECT_EQ(s.find("2/10"), std::string::npos);
  EXPECT_NE(s.find("\rc [###.......]  3/10"), std::string::npos) << s;
  bar.finish();
  const std::string after = out.str();
  EXPECT_EQ(after.back(), '\r');  // the report starts on a clean line
}

TEST(ProgressBar, FinishWithoutDrawingWritesNothing) {
  std::ostringstream out;
  ProgressBar bar(out, "c");
  bar.finish();
  EXPECT_EQ(out.str(), "");
}

}  // namespace
}  // namespace robozoo
