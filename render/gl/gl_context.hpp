#pragma once
// A headless OpenGL context: Mesa's OSMesa (software rendering with llvmpipe;
// no display, no GPU). Draws into an off-screen multisampled framebuffer for
// smooth edges and resolves it into OSMesa's own colour buffer.
#include <string>
#include <vector>

#include "render/gl/image.hpp"

struct osmesa_context;

namespace robozoo::render {

class GlContext {
 public:
  /// A context for width x height images with `samples` samples per pixel
  /// (0 or 1: no multisampling; clamped to what the driver offers). Makes it
  /// current on the calling thread. Throws std::runtime_error when OSMesa
  /// cannot create it, std::invalid_argument for a bad size.
  GlContext(int width, int height, int samples = 4);
  ~GlContext();
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  /// Changes the image size (keeps the context and everything loaded in it).
  void resize(int width, int height);
  /// Makes this context current on the calling thread (one thread at a time).
  void make_current();
  /// Binds the framebuffer to draw into and sets the viewport to the whole image.
  void begin_frame();
  /// Finishes drawing and returns the image (resolved, top row first).
  Image read_image();
  /// The same into an existing image of the right size (no allocation).
  void read_image(Image& out);

  int width() const { return width_; }
  int height() const { return height_; }
  int samples() const { return samples_; }
  /// GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)".
  std::string renderer() const;

 private:
  void create_framebuffer();
  void destroy_framebuffer();

  osmesa_context* ctx_ = nullptr;
  int width_ = 0, height_ = 0;
  int requested_samples_ = 0, samples_ = 0;
  std::vector<unsigned char> buffer_;  // OSMesa's RGBA colour buffer, bottom row first
  unsigned int fbo_ = 0, color_rb_ = 0, depth_rb_ = 0;
};

}  // namespace robozoo::render
