#include "render/scene/overlay.hpp"

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

TEST(Overlay, TargetPointerOnlyWhenTheTargetIsOffScreen) {
  Fonts fonts = Fonts::load(14);
  const Image blank(400, 300, {200, 200, 200});
  Image in_view = blank;
  EXPECT_FALSE(draw_target_pointer(in_view, fonts.regular, {200, 150, 5}, "target 3 m", {240, 176, 32}, 8));
  EXPECT_EQ(in_view.bytes(), blank.bytes());
  // Far to the right: the arrow sits on the right edge, vertically centred.
  Image right = blank;
  EXPECT_TRUE(draw_target_pointer(right, fonts.regular, {5000, 150, 5}, "target 9.0 m", {240, 176, 32}, 8));
  EXPECT_GT(changed(blank, right, 300, 100, 400, 200), 100);
  EXPECT_EQ(changed(blank, right, 0, 0, 150, 300), 0);
  // Behind the eye, projected to the left: the arrow points right.
  Image behind = blank;
  EXPECT_TRUE(draw_target_pointer(behind, fonts.regular, {-100, 150, -2}, "target", {240, 176, 32}, 8));
  EXPECT_GT(changed(blank, behind, 300, 100, 400, 200), 100);
}

}  // namespace
}  // namespace robozoo::render
