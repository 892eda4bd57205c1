#include "render/progress_bar.hpp"

#include <gtest/gtest.h>

#include <cstdio>

namespace robozoo::render {
namespace {

TEST(ProgressBar, Format) {
  EXPECT_EQ(ProgressBar::format("video", 0, 10, 0, 10), "video [..........]   0% 0/10");
  EXPECT_EQ(ProgressBar::format("video", 5, 10, 0, 10), "video [#####.....]  50% 5/10");
  const std::string done = ProgressBar::format("video", 12, 10, 2.0, 4);
  EXPECT_EQ(done.substr(0, 19), "video [####] 100% 1");
  EXPECT_NE(done.find("2.0/s"), std::string::npos);
}

TEST(ProgressBar, SilentWhenDisabledDrawsWhenEnabled) {
  std::FILE* f = std::tmpfile();
  ProgressBar off("x", 3, false, f);
  off.update(1);
  off.finish();
  EXPECT_EQ(std::ftell(f), 0);
  ProgressBar on("x", 3, true, f);
  on.update(3);
  on.finish();
  EXPECT_GT(std::ftell(f), 10);
  std::fclose(f);
}

}  // namespace
}  // namespace robozoo::render
