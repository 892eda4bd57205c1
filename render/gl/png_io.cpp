#include "render/gl/png_io.hpp"

#include <png.h>

#include <cstdio>
#include <memory>
#include <stdexcept>
#include <vector>

namespace robozoo::render {

namespace {

struct FileCloser {
  void operator()(FILE* f) const {
    if (f) std::fclose(f);
  }
};
using FilePtr = std::unique_ptr<FILE, FileCloser>;

[[noreturn]] void png_fail(png_structp png, png_const_charp msg) {
  // libpng requires that this never returns: jump back to the setjmp.
  auto* why = static_cast<std::string*>(png_get_error_ptr(png));
  if (why) *why = msg;
  png_longjmp(png, 1);
}

void png_warn(png_structp, png_const_charp) {}

}  // namespace

void write_png(const std::string& path, const Image& image) {
  if (image.empty()) throw std::runtime_error(path + ": cannot write an empty image");
  const std::string tmp = path + ".part";
  FilePtr f(std::fopen(tmp.c_str(), "wb"));
  if (!f) throw std::runtime_error(path + ": cannot open for writing");
  std::string why;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &why, png_fail, png_warn);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!png || !info) {
    png_destroy_write_struct(&png, &info);
    throw std::runtime_error(path + ": libpng could not start");
  }
  std::vector<png_bytep> rows(static_cast<size_t>(image.height()));
  for (int y = 0; y < image.height(); ++y) rows[static_cast<size_t>(y)] = const_cast<png_bytep>(image.row(y));
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    f.reset();
    std::remove(tmp.c_str());
    throw std::runtime_error(path + ": writing the PNG failed: " + why);
  }
  png_init_io(png, f.get());
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.width()), static_cast<png_uint_32>(image.height()), 8,
               PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_compression_level(png, 6);
  png_write_info(png, info);
  png_write_image(png, rows.data());
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  const bool flushed = std::fflush(f.get()) == 0 && !std::ferror(f.get());
  f.reset();
  if (!flushed || std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw std::runtime_error(path + ": cannot write the file");
  }
}

Image read_png(const std::string& path) {
  FilePtr f(std::fopen(path.c_str(), "rb"));
  if (!f) throw std::runtime_error(path + ": cannot open");
  unsigned char sig[8];
  if (std::fread(sig, 1, 8, f.get()) != 8 || png_sig_cmp(sig, 0, 8) != 0)
    throw std::runtime_error(path + ": not a PNG file");
  std::string why;
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &why, png_fail, png_warn);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!png || !info) {
    png_destroy_read_struct(&png, &info, nullptr);
    throw std::runtime_error(path + ": libpng could not start");
  }
  Image image;
  std::vector<png_bytep> rows;
  std::vector<uint8_t> rgba;
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    throw std::runtime_error(path + ": reading the PNG failed: " + why);
  }
  png_init_io(png, f.get());
  png_set_sig_bytes(png, 8);
  png_read_info(png, info);
  const png_uint_32 w = png_get_image_width(png, info), h = png_get_image_height(png, info);
  // Normalise every PNG to 8-bit RGBA, then drop alpha.
  png_set_expand(png);
  png_set_strip_16(png);
  png_set_gray_to_rgb(png);
  png_set_add_alpha(png, 0xff, PNG_FILLER_AFTER);
  png_read_update_info(png, info);
  if (w == 0 || h == 0 || w > (1u << 15) || h > (1u << 15)) png_error(png, "unsupported image size");
  rgba.resize(static_cast<size_t>(w) * h * 4);
  rows.resize(h);
  for (png_uint_32 y = 0; y < h; ++y) rows[y] = rgba.data() + static_cast<size_t>(y) * w * 4;
  png_read_image(png, rows.data());
  png_read_end(png, nullptr);
  png_destroy_read_struct(&png, &info, nullptr);
  image = Image(static_cast<int>(w), static_cast<int>(h));
  for (png_uint_32 y = 0; y < h; ++y)
    for (png_uint_32 x = 0; x < w; ++x) {
      const uint8_t* p = rgba.data() + (static_cast<size_t>(y) * w + x) * 4;
      image.set(static_cast<int>(x), static_cast<int>(y), {p[0], p[1], p[2]});
    }
  return image;
}

}  // namespace robozoo::render
