#pragma once
// An 8-bit RGB image in memory, rows top to bottom: what the renderer draws
// into, the PNG writer saves and the video encoder consumes.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace robozoo::render {

struct Rgb {
  uint8_t r = 0, g = 0, b = 0;
  bool operator==(const Rgb& o) const { return r == o.r && g == o.g && b == o.b; }
};

class Image {
 public:
  Image() = default;
  /// width x height pixels filled with `fill`; throws std::invalid_argument for
  /// a size that is not positive or too large (more than 2^28 pixels).
  Image(int width, int height, Rgb fill = {});

  int width() const { return width_; }
  int height() const { return height_; }
  bool empty() const { return width_ == 0 || height_ == 0; }
  /// Row-major RGB bytes, 3 per pixel, top row first.
  const std::vector<uint8_t>& bytes() const { return data_; }
  std::vector<uint8_t>& bytes() { return data_; }
  uint8_t* row(int y) { return data_.data() + static_cast<size_t>(y) * width_ * 3; }
  const uint8_t* row(int y) const { return data_.data() + static_cast<size_t>(y) * width_ * 3; }

  Rgb at(int x, int y) const;
  void set(int x, int y, Rgb c);
  /// Mixes `c` into pixel (x, y) with opacity a in [0, 1]; outside the image: nothing.
  void blend(int x, int y, Rgb c, double a);
  /// Fills the rectangle [x, x+w) x [y, y+h) (clipped) with `c` at opacity `a`.
  void fill_rect(int x, int y, int w, int h, Rgb c, double a = 1.0);
  /// Copies `src` with its top-left corner at (x, y) (clipped).
  void paste(const Image& src, int x, int y);

 private:
  int width_ = 0, height_ = 0;
  std::vector<uint8_t> data_;
};

}  // namespace robozoo::render
