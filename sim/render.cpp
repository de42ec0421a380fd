#include "sim/render.h"

#include <fmt/format.h>

#include "sim/config.h"
#include "sim/gl_window.h"
#include "sim/scene_draw.h"

namespace tactip {

void CheckImageSide(const char* what, int value) {
  if (value < kMinImageSide || value > kMaxImageSide) {
    throw InputError(fmt::format("{} = {}: must be in [{}, {}] pixels", what, value, kMinImageSide, kMaxImageSide));
  }
}

SceneRenderer::SceneRenderer(const CompiledModel& model, int width, int height) : width_(width), height_(height) {
  CheckImageSide("image width", width);
  CheckImageSide("image height", height);
  // A hidden window only provides the OpenGL context; drawing goes to the offscreen buffer.
  window_ = std::make_unique<GlWindow>(width, height, false, "tactip render");
  draw_ = std::make_unique<SceneDraw>(model, width, height);
  draw_->UseBuffer(mjFB_OFFSCREEN);
}

SceneRenderer::~SceneRenderer() {
  // The OpenGL resources are freed in their own context.
  window_->MakeCurrent();
  draw_.reset();
}

void SceneRenderer::SetView(const CameraView& view) { draw_->SetView(view); }

RgbImage SceneRenderer::Render(const Simulation& sim, const RenderOptions& options) {
  window_->MakeCurrent();
  draw_->UseBuffer(mjFB_OFFSCREEN);
  const mjrRect viewport{0, 0, width_, height_};
  draw_->Draw(sim, options, viewport);
  return draw_->Read(viewport);
}

}  // namespace tactip
