#include "render/gl/png_io.hpp"

#include <fcntl.h>  // tests/support/subprocess.hpp uses open()
#include <gtest/gtest.h>

#include <fstream>

#include "tests/support/subprocess.hpp"

namespace robozoo::render {
namespace {

using robozoo::testing::TempDir;

TEST(PngIo, RoundTripsEveryPixel) {
  TempDir dir;
  Image img(17, 9);
  for (int y = 0; y < img.height(); ++y)
    for (int x = 0; x < img.width(); ++x)
      img.set(x, y, {static_cast<uint8_t>(x * 15), static_cast<uint8_t>(y * 28), static_cast<uint8_t>(x ^ y)});
  write_png(dir / "a.png", img);
  const Image back = read_png(dir / "a.png");
  ASSERT_EQ(back.width(), 17);
  ASSERT_EQ(back.height(), 9);
  EXPECT_EQ(back.bytes(), img.bytes());
  EXPECT_FALSE(robozoo::testing::file_exists(dir / "a.png.part"));
}

TEST(PngIo, ClearErrors) {
  TempDir dir;
  try {
    read_png(dir / "missing.png");
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("missing.png"), std::string::npos);
  }
  std::ofstream(dir / "not.png") << "hello, not a png";
  EXPECT_THROW(read_png(dir / "not.png"), std::runtime_error);
  EXPECT_THROW(write_png(dir / "no/such/folder/x.png", Image(2, 2)), std::runtime_error);
  EXPECT_THROW(write_png(dir / "empty.png", Image()), std::runtime_error);
}

}  // namespace
}  // namespace robozoo::render
