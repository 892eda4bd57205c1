#pragma once
// A headless OpenGL context with the scene renderer in it: the one place that
// turns a SceneView and a Camera into an Image. Zoo sheets, videos, live mode
// and the benchmark all draw through a Stage.
#include <memory>

#include "render/gl/camera.hpp"
#include "render/gl/gl_context.hpp"
#include "render/gl/image.hpp"
#include "render/scene/scene.hpp"

namespace robozoo::render {

class Stage {
 public:
  /// Throws like GlContext (no OSMesa) or SceneRenderer (no GLSL).
  Stage(int width, int height, int samples = 4, const SceneStyle& style = {});
  /// Changes the image size.
  void resize(int width, int height);
  /// Draws and reads back.
  Image render(const SceneView& view, const Camera& camera);
  void render(const SceneView& view, const Camera& camera, Image& out);
  int width() const { return context_->width(); }
  int height() const { return context_->height(); }
  double aspect() const { return static_cast<double>(width()) / height(); }
  GlContext& context() { return *context_; }
  SceneRenderer& scene() { return *scene_; }

 private:
  std::unique_ptr<GlContext> context_;
  std::unique_ptr<SceneRenderer> scene_;
};

}  // namespace robozoo::render
