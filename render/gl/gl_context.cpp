#include "render/gl/gl_context.hpp"

// gl.hpp first: it asks GL/gl.h for the extension prototypes, and osmesa.h includes GL/gl.h.
#include "render/gl/gl.hpp"
#include <GL/osmesa.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>

namespace robozoo::render {

namespace {
void check_size(int width, int height) {
  if (width <= 0 || height <= 0 || width > 16384 || height > 16384)
    throw std::invalid_argument("render size must be between 1x1 and 16384x16384, got " + std::to_string(width) + "x" +
                                std::to_string(height));
}
}  // namespace

GlContext::GlContext(int width, int height, int samples) : requested_samples_(samples) {
  check_size(width, height);
  const int attribs[] = {OSMESA_FORMAT,
                         OSMESA_RGBA,
                         OSMESA_DEPTH_BITS,
                         24,
                         OSMESA_STENCIL_BITS,
                         8,
                         OSMESA_PROFILE,
                         OSMESA_COMPAT_PROFILE,
                         OSMESA_CONTEXT_MAJOR_VERSION,
                         2,
                         OSMESA_CONTEXT_MINOR_VERSION,
                         1,
                         0};
  ctx_ = OSMesaCreateContextAttribs(attribs, nullptr);
  if (!ctx_) throw std::runtime_error("OSMesa could not create an OpenGL context (is libosmesa6 installed?)");
  width_ = width;
  height_ = height;
  buffer_.assign(static_cast<size_t>(width_) * height_ * 4, 0);
  make_current();
  create_framebuffer();
}

GlContext::~GlContext() {
  if (ctx_) {
    make_current();
    destroy_framebuffer();
    OSMesaDestroyContext(ctx_);
  }
}

void GlContext::make_current() {
  if (!OSMesaMakeCurrent(ctx_, buffer_.data(), GL_UNSIGNED_BYTE, width_, height_))
    throw std::runtime_error("OSMesaMakeCurrent failed for a " + std::to_string(width_) + "x" +
                             std::to_string(height_) + " buffer");
}

void GlContext::resize(int width, int height) {
  check_size(width, height);
  if (width == width_ && height == height_) return;
  width_ = width;
  height_ = height;
  buffer_.assign(static_cast<size_t>(width_) * height_ * 4, 0);
  make_current();
  destroy_framebuffer();
  create_framebuffer();
}

void GlContext::create_framebuffer() {
  samples_ = 0;
  if (requested_samples_ <= 1) return;
  GLint max_samples = 0;
  glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
  const int samples = std::min(requested_samples_, static_cast<int>(max_samples));
  if (samples <= 1) return;
  glGenFramebuffers(1, &fbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glGenRenderbuffers(1, &color_rb_);
  glBindRenderbuffer(GL_RENDERBUFFER, color_rb_);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA8, width_, height_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_rb_);
  glGenRenderbuffers(1, &depth_rb_);
  glBindRenderbuffer(GL_RENDERBUFFER, depth_rb_);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH24_STENCIL8, width_, height_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_rb_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_RENDERBUFFER, depth_rb_);
  const bool complete = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (!complete) {
    destroy_framebuffer();  // draw without multisampling
    return;
  }
  samples_ = samples;
}

void GlContext::destroy_framebuffer() {
  if (fbo_) glDeleteFramebuffers(1, &fbo_);
  if (color_rb_) glDeleteRenderbuffers(1, &color_rb_);
  if (depth_rb_) glDeleteRenderbuffers(1, &depth_rb_);
  fbo_ = color_rb_ = depth_rb_ = 0;
  samples_ = 0;
}

void GlContext::begin_frame() {
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glViewport(0, 0, width_, height_);
}

Image GlContext::read_image() {
  Image out(width_, height_);
  read_image(out);
  return out;
}

void GlContext::read_image(Image& out) {
  if (out.width() != width_ || out.height() != height_) out = Image(width_, height_);
  if (fbo_) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
  }
  glFinish();
  // OSMesa's buffer holds RGBA with the bottom row first.
  for (int y = 0; y < height_; ++y) {
    const unsigned char* src = buffer_.data() + static_cast<size_t>(height_ - 1 - y) * width_ * 4;
    uint8_t* dst = out.row(y);
    // Four bytes a pixel, the fourth overwritten by the next pixel's red.
    for (int x = 0; x + 1 < width_; ++x) std::memcpy(dst + 3 * x, src + 4 * x, 4);
    std::memcpy(dst + 3 * (width_ - 1), src + 4 * (width_ - 1), 3);
  }
}

std::string GlContext::renderer() const {
  const auto* s = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return s ? s : "";
}

}  // namespace robozoo::render
