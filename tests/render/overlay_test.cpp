#include "render/overlay.hpp"

#include <gtest/gtest.h>

namespace robozoo::render {
namespace {

int changed(const Image& a, const Image& b, int x0, int y0, int x1, int y1) {
  int n = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) n += !(a.at(x, y) == b.at(x, y));
  return n;
}

TEST(Overlay, PanelInTheTopLeftLegendInTheBottomRight) {
  Fonts fonts = Fonts::load(16);
  const Image blank(640, 360, {200, 200, 200});
  Image img = blank;
  draw_overlay(img, fonts, OverlayText{"run \u00b7 genome 4", {"generation 3", "t = 1.00 s"}, 0.5}, 10);
  EXPECT_GT(changed(blank, img, 0, 0, 320, 180), 5000);
  EXPECT_EQ(changed(blank, img, 320, 180, 640, 360), 0);
  EXPECT_LT(img.at(12, 12).r, 150);  // the panel darkens
  Image legend = blank;
  draw_legend(legend, fonts.regular, {214, 44, 36}, {40, 88, 204}, 10);
  EXPECT_GT(changed(blank, legend, 320, 180, 640, 360), 500);
  EXPECT_EQ(changed(blank, legend, 0, 0, 320, 180), 0);
}

}  // namespace
}  // namespace robozoo::render
