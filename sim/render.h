#pragma once
// Offscreen rendering of a Simulation's state into an RGB image with MuJoCo's OpenGL
// renderer, through a hidden GLFW window (headless under Xvfb: `xvfb-run -a tactip ...`).

#include <memory>

#include "sim/render_types.h"
#include "sim/simulation.h"

namespace tactip {

class GlWindow;
class SceneDraw;

/// Smallest and largest image side the renderer accepts (pixels).
inline constexpr int kMinImageSide = 16;
inline constexpr int kMaxImageSide = 4096;

/// Renders states of one model into images of a fixed size. Holds its own OpenGL context
/// (and a copy of the model's visual settings); main thread only (GLFW's rule).
class SceneRenderer {
 public:
  /// Opens a hidden `width` x `height` window for `model`. Throws InputError when a side is
  /// outside [kMinImageSide, kMaxImageSide] or no display is available ("no display: run
  /// under xvfb-run or set DISPLAY"). The model must outlive the renderer's Render calls.
  SceneRenderer(const CompiledModel& model, int width, int height);
  ~SceneRenderer();
  SceneRenderer(const SceneRenderer&) = delete;
  SceneRenderer& operator=(const SceneRenderer&) = delete;

  /// Points the camera (default: a free camera framing the model's extent).
  void SetView(const CameraView& view);
  /// Renders the current state of `sim` (a Simulation of the same model) with `options`.
  RgbImage Render(const Simulation& sim, const RenderOptions& options);

  int width() const { return width_; }
  int height() const { return height_; }

 private:
  int width_, height_;
  std::unique_ptr<GlWindow> window_;  // the OpenGL context (destroyed after draw_)
  std::unique_ptr<SceneDraw> draw_;
};

/// Throws InputError unless `value` is a valid image side; `what` names it in the message
/// (e.g. "--width").
void CheckImageSide(const char* what, int value);

}  // namespace tactip
