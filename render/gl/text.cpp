#include "render/gl/text.hpp"

#include <ft2build.h>
#include FT_FREETYPE_H

#include <sys/stat.h>

#include <algorithm>
#include <stdexcept>
#include <vector>

namespace robozoo::render {

#ifndef ROBOZOO_DEFAULT_FONT_DIR
#define ROBOZOO_DEFAULT_FONT_DIR "/usr/share/fonts/truetype/dejavu"
#endif

std::string font_path(const std::string& file, const std::string& dir) {
  const std::string path = (dir.empty() ? std::string(ROBOZOO_DEFAULT_FONT_DIR) : dir) + "/" + file;
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0)
    throw std::runtime_error("font " + path + " not found (Debian package fonts-dejavu-core; or pass --font-dir)");
  return path;
}

std::u32string decode_utf8(const std::string& s) {
  std::u32string out;
  size_t i = 0;
  while (i < s.size()) {
    const auto c = static_cast<unsigned char>(s[i]);
    int n = 0;
    char32_t cp = 0;
    if (c < 0x80) {
      cp = c;
    } else if ((c & 0xe0) == 0xc0) {
      n = 1;
      cp = c & 0x1f;
    } else if ((c & 0xf0) == 0xe0) {
      n = 2;
      cp = c & 0x0f;
    } else if ((c & 0xf8) == 0xf0) {
      n = 3;
      cp = c & 0x07;
    } else {
      out.push_back(0xfffd);
      ++i;
      continue;
    }
    bool ok = i + static_cast<size_t>(n) < s.size();  // the continuation bytes are there
    for (int k = 1; ok && k <= n; ++k) {
      const auto d = static_cast<unsigned char>(s[i + k]);
      if ((d & 0xc0) != 0x80) ok = false;
      cp = (cp << 6) | (d & 0x3f);
    }
    if (!ok) {
      out.push_back(0xfffd);
      ++i;
      continue;
    }
    out.push_back(cp);
    i += static_cast<size_t>(n) + 1;
  }
  return out;
}

struct Font::Glyph {
  int width = 0, rows = 0, left = 0, top = 0, advance = 0;  // pixels
  unsigned int index = 0;                                   // FreeType glyph index
  std::vector<uint8_t> coverage;                            // rows * width
};

struct Font::Impl {
  FT_Library library = nullptr;
  FT_Face face = nullptr;

  /// Pixels to move the pen between glyphs `prev` (0: none) and `next`.
  int kerning(unsigned int prev, unsigned int next) const {
    FT_Vector k;
    if (prev == 0 || !FT_HAS_KERNING(face) || FT_Get_Kerning(face, prev, next, FT_KERNING_DEFAULT, &k) != 0) return 0;
    return static_cast<int>(k.x >> 6);
  }
  std::map<char32_t, Glyph> cache;
  ~Impl() {
    if (face) FT_Done_Face(face);
    if (library) FT_Done_FreeType(library);
  }
};

Font::Font(const std::string& path, int pixel_size) : impl_(std::make_unique<Impl>()), size_(pixel_size) {
  if (pixel_size < 4 || pixel_size > 512)
    throw std::invalid_argument("font size must be in [4, 512] pixels, got " + std::to_string(pixel_size));
  if (FT_Init_FreeType(&impl_->library) != 0) throw std::runtime_error("FreeType could not start");
  if (FT_New_Face(impl_->library, path.c_str(), 0, &impl_->face) != 0)
    throw std::runtime_error("FreeType cannot load the font " + path);
  if (FT_Set_Pixel_Sizes(impl_->face, 0, static_cast<FT_UInt>(pixel_size)) != 0)
    throw std::runtime_error("FreeType cannot size the font " + path);
}

Font::~Font() = default;
Font::Font(Font&&) noexcept = default;
Font& Font::operator=(Font&&) noexcept = default;

int Font::ascender() const { return static_cast<int>(impl_->face->size->metrics.ascender >> 6); }
int Font::descender() const { return static_cast<int>(-(impl_->face->size->metrics.descender >> 6)); }
int Font::line_height() const { return static_cast<int>(impl_->face->size->metrics.height >> 6); }

const Font::Glyph& Font::glyph(char32_t c) {
  auto it = impl_->cache.find(c);
  if (it != impl_->cache.end()) return it->second;
  Glyph g;
  FT_Face face = impl_->face;
  g.index = FT_Get_Char_Index(face, c);
  if (g.index == 0) g.index = FT_Get_Char_Index(face, '?');
  if (FT_Load_Glyph(face, g.index, FT_LOAD_RENDER | FT_LOAD_TARGET_LIGHT) == 0) {
    const FT_Bitmap& bm = face->glyph->bitmap;
    g.width = static_cast<int>(bm.width);
    g.rows = static_cast<int>(bm.rows);
    g.left = face->glyph->bitmap_left;
    g.top = face->glyph->bitmap_top;
    g.advance = static_cast<int>((face->glyph->advance.x + 32) >> 6);
    g.coverage.resize(static_cast<size_t>(g.width) * g.rows);
    for (int y = 0; y < g.rows; ++y)
      std::copy(bm.buffer + y * bm.pitch, bm.buffer + y * bm.pitch + g.width,
                g.coverage.begin() + static_cast<ptrdiff_t>(y) * g.width);
  }
  return impl_->cache.emplace(c, std::move(g)).first->second;
}

int Font::measure(const std::string& utf8) {
  int x = 0;
  unsigned int prev = 0;
  for (char32_t c : decode_utf8(utf8)) {
    const Glyph& g = glyph(c);
    x += impl_->kerning(prev, g.index);
    x += g.advance;
    prev = g.index;
  }
  return x;
}

int Font::draw(Image& image, int x, int baseline, const std::string& utf8, Rgb color, double opacity) {
  unsigned int prev = 0;
  for (char32_t c : decode_utf8(utf8)) {
    const Glyph& g = glyph(c);
    x += impl_->kerning(prev, g.index);
    for (int y = 0; y < g.rows; ++y)
      for (int gx = 0; gx < g.width; ++gx) {
        const uint8_t a = g.coverage[static_cast<size_t>(y) * g.width + gx];
        if (a) image.blend(x + g.left + gx, baseline - g.top + y, color, opacity * a / 255.0);
      }
    x += g.advance;
    prev = g.index;
  }
  return x;
}

Fonts Fonts::load(int pixel_size, const std::string& dir) {
  return Fonts{Font(font_path("DejaVuSans.ttf", dir), pixel_size),
               Font(font_path("DejaVuSans-Bold.ttf", dir), pixel_size)};
}

}  // namespace robozoo::render
