#pragma once
// PNG files through libpng: 8-bit RGB, no interlacing.
#include <string>

#include "render/gl/image.hpp"

namespace robozoo::render {

/// Writes `image` to `path` as an 8-bit RGB PNG. Writes a temporary file next
/// to it first and renames it into place, so a reader never sees half a PNG.
/// Throws std::runtime_error naming the path on failure.
void write_png(const std::string& path, const Image& image);

/// Reads an 8-bit (or lower, expanded) gray/RGB/RGBA PNG into RGB (alpha is
/// dropped). Throws std::runtime_error naming the path on failure.
Image read_png(const std::string& path);

}  // namespace robozoo::render
