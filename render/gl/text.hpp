#pragma once
// Text in images with FreeType and a real font (DejaVu, from Debian's
// fonts-dejavu-core): anti-aliased glyphs blended into an Image.
#include <map>
#include <memory>
#include <string>

#include "render/gl/image.hpp"

namespace robozoo::render {

/// Path of a DejaVu font file by name (e.g. "DejaVuSans.ttf") in `dir`
/// (empty: the build's default, /usr/share/fonts/truetype/dejavu). Throws
/// std::runtime_error naming the path when it is missing.
std::string font_path(const std::string& file, const std::string& dir = "");

class Font {
 public:
  /// Loads the font file at a size in pixels (em height). Throws
  /// std::runtime_error naming the file when FreeType cannot load it, and
  /// std::invalid_argument for a size outside [4, 512].
  Font(const std::string& path, int pixel_size);
  ~Font();
  Font(Font&&) noexcept;
  Font& operator=(Font&&) noexcept;

  int pixel_size() const { return size_; }
  int ascender() const;     ///< pixels above the baseline
  int descender() const;    ///< pixels below the baseline (positive)
  int line_height() const;  ///< baseline to baseline (pixels)
  /// Advance width of a UTF-8 string (pixels).
  int measure(const std::string& utf8);
  /// Draws a UTF-8 string with its baseline starting at (x, baseline);
  /// returns the pen position after it. Invalid UTF-8 bytes are drawn as '?'.
  int draw(Image& image, int x, int baseline, const std::string& utf8, Rgb color, double opacity = 1.0);

 private:
  struct Glyph;
  struct Impl;
  const Glyph& glyph(char32_t c);
  std::unique_ptr<Impl> impl_;
  int size_ = 0;
};

/// The two faces labels use.
struct Fonts {
  Font regular;
  Font bold;
  /// DejaVuSans.ttf and DejaVuSans-Bold.ttf from `dir` at `pixel_size`.
  static Fonts load(int pixel_size, const std::string& dir = "");
};

/// Decodes UTF-8 into code points; invalid bytes become U+FFFD.
std::u32string decode_utf8(const std::string& s);

}  // namespace robozoo::render
