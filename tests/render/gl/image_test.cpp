#include "render/gl/image.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <stdexcept>

namespace robozoo::render {
namespace {

TEST(Image, FilledOnCreation) {
  const Image img(4, 3, {10, 20, 30});
  EXPECT_EQ(img.width(), 4);
  EXPECT_EQ(img.height(), 3);
  EXPECT_EQ(img.bytes().size(), 4u * 3u * 3u);
  EXPECT_EQ(img.at(3, 2), (Rgb{10, 20, 30}));
}

TEST(Image, RejectsBadSizes) {
  EXPECT_THROW(Image(0, 5), std::invalid_argument);
  EXPECT_THROW(Image(5, -1), std::invalid_argument);
  EXPECT_THROW(Image(1 << 15, 1 << 15), std::invalid_argument);
}

TEST(Image, BlendMixesAndClips) {
  Image img(2, 2, {0, 0, 0});
  img.blend(0, 0, {200, 100, 50}, 0.5);
  EXPECT_EQ(img.at(0, 0), (Rgb{100, 50, 25}));
  img.blend(1, 1, {255, 255, 255}, 1.0);
  EXPECT_EQ(img.at(1, 1), (Rgb{255, 255, 255}));
  img.blend(5, 5, {1, 1, 1}, 1.0);  // outside: nothing, no crash
  img.set(-1, 0, {1, 1, 1});
  EXPECT_THROW(img.at(2, 0), std::out_of_range);
}

TEST(Image, FillRectAndPasteAreClipped) {
  Image dst(5, 4, {0, 0, 0});
  dst.fill_rect(3, 2, 10, 10, {9, 9, 9});
  EXPECT_EQ(dst.at(4, 3), (Rgb{9, 9, 9}));
  EXPECT_EQ(dst.at(2, 2), (Rgb{0, 0, 0}));
  const Image src(3, 3, {7, 8, 9});
  dst.paste(src, -1, -1);  // only its bottom-right 2x2 lands
  EXPECT_EQ(dst.at(0, 0), (Rgb{7, 8, 9}));
  EXPECT_EQ(dst.at(1, 1), (Rgb{7, 8, 9}));
  EXPECT_EQ(dst.at(2, 0), (Rgb{0, 0, 0}));
  EXPECT_EQ(dst.at(2, 2), (Rgb{0, 0, 0}));
}

TEST(Image, TranslucentFillRectIsBlendOnEachPixel) {
  // fill_rect looks blended bytes up in a table; blend() computes each pixel.
  Image base(40, 30);
  uint32_t state = 12345;
  auto next = [&] { return static_cast<uint8_t>((state = state * 1103515245u + 12345u) >> 23); };
  for (int y = 0; y < 30; ++y)
    for (int x = 0; x < 40; ++x) base.set(x, y, {next(), next(), next()});
  for (const double a : {0.0, -0.5, 1e-9, 0.13, 0.5, 0.5 + 1e-12, 0.85, 0.999, 1.0, 2.0, std::nan("")}) {
    Image by_rect = base, by_pixel = base;
    const Rgb c{next(), next(), next()};
    by_rect.fill_rect(-3, 5, 30, 40, c, a);
    for (int y = 5; y < 30; ++y)
      for (int x = 0; x < 27; ++x) {
        if (a >= 1.0)
          by_pixel.set(x, y, c);
        else
          by_pixel.blend(x, y, c, a);
      }
    EXPECT_EQ(by_rect.bytes(), by_pixel.bytes()) << "alpha " << a;
  }
}

}  // namespace
}  // namespace robozoo::render
