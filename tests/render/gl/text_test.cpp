#include "render/gl/text.hpp"

#include <gtest/gtest.h>

namespace robozoo::render {
namespace {

int dark_pixels(const Image& img, int x0, int y0, int x1, int y1) {
  int n = 0;
  for (int y = std::max(0, y0); y < std::min(img.height(), y1); ++y)
    for (int x = std::max(0, x0); x < std::min(img.width(), x1); ++x) n += img.at(x, y).r < 128;
  return n;
}

TEST(Text, DejaVuDrawsInsideItsMeasuredBox) {
  Font font(font_path("DejaVuSans.ttf"), 20);
  EXPECT_GT(font.ascender(), 10);
  EXPECT_GT(font.line_height(), font.ascender());
  Image img(300, 60, {255, 255, 255});
  const std::string s = "generation 12 \u00b7 fitness 15.42";
  const int w = font.measure(s);
  EXPECT_GT(w, 150);
  EXPECT_LT(w, 300);
  const int end = font.draw(img, 10, 40, s, {0, 0, 0});
  EXPECT_EQ(end, 10 + w);
  const int inside = dark_pixels(img, 10, 40 - font.ascender(), 10 + w + 2, 40 + font.descender() + 1);
  EXPECT_GT(inside, 100);
  EXPECT_EQ(dark_pixels(img, 0, 0, 300, 60), inside);  // nothing outside the box
  // Anti-aliased: some pixels are neither white nor black.
  int grey = 0;
  for (int y = 0; y < img.height(); ++y)
    for (int x = 0; x < img.width(); ++x) grey += img.at(x, y).r > 30 && img.at(x, y).r < 225;
  EXPECT_GT(grey, 20);
}

TEST(Text, BoldIsWiderThanRegular) {
  Fonts f = Fonts::load(16);
  EXPECT_GT(f.bold.measure("feedforward-s7"), f.regular.measure("feedforward-s7"));
}

TEST(Text, ClearErrors) {
  EXPECT_THROW(font_path("DejaVuSans.ttf", "/no/such/dir"), std::runtime_error);
  EXPECT_THROW(Font("/no/such/font.ttf", 12), std::runtime_error);
  EXPECT_THROW(Font(font_path("DejaVuSans.ttf"), 2), std::invalid_argument);
}

TEST(Text, DecodesUtf8AndReplacesBadBytes) {
  EXPECT_EQ(decode_utf8("a\u00b7\u00d7"), (std::u32string{U'a', 0xb7, 0xd7}));
  EXPECT_EQ(decode_utf8(std::string("a\xff"
                                    "b")),
            (std::u32string{U'a', 0xfffd, U'b'}));
  EXPECT_EQ(decode_utf8(std::string("\xe2\x82")), (std::u32string{0xfffd, 0xfffd}));  // cut short
}

}  // namespace
}  // namespace robozoo::render
