#include "render/scene/stage.hpp"

namespace robozoo::render {

Stage::Stage(int width, int height, int samples, const SceneStyle& style)
    : context_(std::make_unique<GlContext>(width, height, samples)), scene_(std::make_unique<SceneRenderer>(style)) {}

void Stage::resize(int width, int height) { context_->resize(width, height); }

Image Stage::render(const SceneView& view, const Camera& camera) {
  Image out;
  render(view, camera, out);
  return out;
}

void Stage::render(const SceneView& view, const Camera& camera, Image& out) {
  context_->make_current();
  context_->begin_frame();
  scene_->draw(view, camera, width(), height());
  context_->read_image(out);
}

}  // namespace robozoo::render
