#pragma once
// MuJoCo's abstract scene and OpenGL resources for one model: turns a Simulation's state
// into OpenGL drawing in the current context. Internal to sim/ (SceneRenderer, ViewerWindow).

#include <mujoco/mujoco.h>

#include <memory>
#include <string>
#include <vector>

#include "sim/render_types.h"
#include "sim/simulation.h"

namespace tactip {

/// Draws one model's states. Needs an OpenGL context current when it is constructed,
/// used and destroyed (the same context each time).
class SceneDraw {
 public:
  /// Uploads the model to the current context, with an offscreen buffer of
  /// `offscreen_width` x `offscreen_height` pixels.
  SceneDraw(const CompiledModel& model, int offscreen_width, int offscreen_height);
  ~SceneDraw();
  SceneDraw(const SceneDraw&) = delete;
  SceneDraw& operator=(const SceneDraw&) = delete;

  /// Points the camera as `view` says (its bodies are followed in every frame after).
  void SetView(const CameraView& view);
  /// Turns the camera about the look-at point; dx, dy are fractions of the window height.
  void Orbit(double dx, double dy);
  /// Moves the camera closer (dy < 0) or farther (dy > 0); dy as a fraction of the height.
  void Zoom(double dy);

  /// Draws `sim`'s state with `options` into `viewport` of the current buffer.
  void Draw(const Simulation& sim, const RenderOptions& options, mjrRect viewport);
  /// Selects the offscreen buffer (mjFB_OFFSCREEN) or the window's (mjFB_WINDOW).
  void UseBuffer(int framebuffer);
  /// Reads `viewport` of the current buffer as RGB rows, top row first.
  RgbImage Read(mjrRect viewport) const;
  /// Writes `text` in the top-left corner of `viewport` of the current buffer.
  void Overlay(mjrRect viewport, const std::string& text);

 private:
  void FollowBodies(const mjData* d);
  void ApplyOverrides(const RenderOptions& options);

  std::unique_ptr<mjModel, MjModelDeleter> model_;  // this viewer's copy (visual settings)
  double default_force_scale_ = 0.0;                // the model's vis.map.force
  std::vector<int> follow_;                         // bodies the camera looks at
  std::vector<const Rgba*> colour_of_geom_;         // per geom: override or null (per frame)
  std::vector<char> hidden_;                        // per geom: left out (per frame)
  mjvScene scene_;
  mjvOption option_;
  mjvCamera camera_;
  mjrContext context_;
};

}  // namespace tactip
