#include "render/gl/image.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

namespace robozoo::render {

namespace {
/// `dst` moved towards `src` by `a` (0-1), rounded to the nearest byte.
uint8_t mix(uint8_t dst, uint8_t src, double a) {
  return static_cast<uint8_t>(std::lround(dst + (static_cast<double>(src) - dst) * a));
}
}  // namespace

Image::Image(int width, int height, Rgb fill) : width_(width), height_(height) {
  if (width <= 0 || height <= 0 || static_cast<int64_t>(width) * height > (int64_t{1} << 28))
    throw std::invalid_argument("image size must be positive and at most 2^28 pixels, got " + std::to_string(width) +
                                "x" + std::to_string(height));
  data_.resize(static_cast<size_t>(width) * height * 3);
  for (size_t i = 0; i < data_.size(); i += 3) {
    data_[i] = fill.r;
    data_[i + 1] = fill.g;
    data_[i + 2] = fill.b;
  }
}

Rgb Image::at(int x, int y) const {
  if (x < 0 || y < 0 || x >= width_ || y >= height_)
    throw std::out_of_range("pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") outside a " +
                            std::to_string(width_) + "x" + std::to_string(height_) + " image");
  const uint8_t* p = row(y) + 3 * x;
  return {p[0], p[1], p[2]};
}

void Image::set(int x, int y, Rgb c) {
  if (x < 0 || y < 0 || x >= width_ || y >= height_) return;
  uint8_t* p = row(y) + 3 * x;
  p[0] = c.r;
  p[1] = c.g;
  p[2] = c.b;
}

void Image::blend(int x, int y, Rgb c, double a) {
  if (x < 0 || y < 0 || x >= width_ || y >= height_ || !(a > 0)) return;
  a = std::min(a, 1.0);
  uint8_t* p = row(y) + 3 * x;
  p[0] = mix(p[0], c.r, a);
  p[1] = mix(p[1], c.g, a);
  p[2] = mix(p[2], c.b, a);
}

void Image::fill_rect(int x, int y, int w, int h, Rgb c, double a) {
  const int x0 = std::max(x, 0), y0 = std::max(y, 0);
  const int x1 = std::min(x + w, width_), y1 = std::min(y + h, height_);
  if (x1 <= x0 || y1 <= y0 || !(a > 0)) return;
  // What blend() makes of each possible byte, per channel: the same values,
  // computed 768 times instead of three times a pixel.
  std::array<std::array<uint8_t, 256>, 3> to{};
  const uint8_t src[3] = {c.r, c.g, c.b};
  for (int ch = 0; ch < 3; ++ch)
    for (int v = 0; v < 256; ++v) to[ch][v] = a >= 1.0 ? src[ch] : mix(static_cast<uint8_t>(v), src[ch], a);
  for (int yy = y0; yy < y1; ++yy) {
    uint8_t* p = row(yy) + 3 * x0;
    for (int xx = x0; xx < x1; ++xx, p += 3) {
      p[0] = to[0][p[0]];
      p[1] = to[1][p[1]];
      p[2] = to[2][p[2]];
    }
  }
}

void Image::paste(const Image& src, int x, int y) {
  const int x0 = std::max(x, 0), x1 = std::min(x + src.width(), width_);
  if (x1 <= x0) return;
  for (int sy = 0; sy < src.height(); ++sy) {
    const int dy = y + sy;
    if (dy < 0 || dy >= height_) continue;
    std::memcpy(row(dy) + 3 * x0, src.row(sy) + 3 * (x0 - x), static_cast<size_t>(x1 - x0) * 3);
  }
}

}  // namespace robozoo::render
