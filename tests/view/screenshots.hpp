#pragma once
// Test support for the browser tests of tests/view: keeping a screenshot (and a
// copy in the folder ROBOZOO_VIEW_SHOTS names, to look at) and comparing two.
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "render/gl/image.hpp"
#include "render/gl/png_io.hpp"

namespace robozoo::testing {

/// Writes the PNG bytes to `path` (and a copy into ROBOZOO_VIEW_SHOTS when set) and decodes them.
inline render::Image keep_png(const std::vector<uint8_t>& png, const std::string& path) {
  std::vector<std::string> paths = {path};
  if (const char* keep = std::getenv("ROBOZOO_VIEW_SHOTS"))
    paths.push_back(std::string(keep) + "/" + path.substr(path.rfind('/') + 1));
  for (const std::string& p : paths)
    std::ofstream(p, std::ios::binary)
        .write(reinterpret_cast<const char*>(png.data()), static_cast<std::streamsize>(png.size()));
  return render::read_png(path);
}

/// Pixels that differ by more than a little (a summed RGB difference over 30)
/// between two pictures of one size; -1 when the sizes differ.
inline int changed_pixels(const render::Image& a, const render::Image& b) {
  if (a.width() != b.width() || a.height() != b.height()) return -1;
  int n = 0;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x) {
      const render::Rgb p = a.at(x, y), q = b.at(x, y);
      n += std::abs(p.r - q.r) + std::abs(p.g - q.g) + std::abs(p.b - q.b) > 30;
    }
  return n;
}

}  // namespace robozoo::testing
