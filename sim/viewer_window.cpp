#include "sim/viewer_window.h"

#include <GLFW/glfw3.h>

#include <chrono>

#include "sim/gl_window.h"
#include "sim/render.h"
#include "sim/scene_draw.h"
#include "sim/viewer_controls.h"

namespace tactip {

struct ViewerWindow::State {
  std::unique_ptr<GlWindow> window;  // destroyed after draw
  std::unique_ptr<SceneDraw> draw;
  ViewerControls controls;
  std::string title;  // the window's title without the source's status
  bool left_down = false, right_down = false;  // mouse buttons held
  double mouse_x = 0.0, mouse_y = 0.0;         // last cursor position (screen pixels)
};

namespace {

ViewerWindow::State& StateOf(GLFWwindow* w) { return *static_cast<ViewerWindow::State*>(glfwGetWindowUserPointer(w)); }

// Keys -> viewer commands (repeats of the step key step again).
void OnKey(GLFWwindow* w, int key, int /*scancode*/, int action, int /*mods*/) {
  if (action == GLFW_RELEASE) return;
  ViewerControls& c = StateOf(w).controls;
  switch (key) {
    case GLFW_KEY_SPACE: if (action == GLFW_PRESS) c.Apply(ViewerCommand::kPauseResume); break;
    case GLFW_KEY_RIGHT:
    case GLFW_KEY_PERIOD: c.Apply(ViewerCommand::kSingleStep); break;
    case GLFW_KEY_MINUS:
    case GLFW_KEY_KP_SUBTRACT: if (action == GLFW_PRESS) c.Apply(ViewerCommand::kSlower); break;
    case GLFW_KEY_EQUAL:  // '+' is shift + '=' on most layouts
    case GLFW_KEY_KP_ADD: if (action == GLFW_PRESS) c.Apply(ViewerCommand::kFaster); break;
    case GLFW_KEY_F: if (action == GLFW_PRESS) c.Apply(ViewerCommand::kToggleForces); break;
    case GLFW_KEY_ESCAPE: c.Apply(ViewerCommand::kQuit); break;
    default: break;
  }
}

void OnMouseButton(GLFWwindow* w, int button, int action, int /*mods*/) {
  ViewerWindow::State& s = StateOf(w);
  const bool down = action == GLFW_PRESS;
  if (button == GLFW_MOUSE_BUTTON_LEFT) s.left_down = down;
  if (button == GLFW_MOUSE_BUTTON_RIGHT) s.right_down = down;
  glfwGetCursorPos(w, &s.mouse_x, &s.mouse_y);
}

// Left drag orbits, right drag zooms; moves are fractions of the window height.
void OnCursor(GLFWwindow* w, double x, double y) {
  ViewerWindow::State& s = StateOf(w);
  const double dx = x - s.mouse_x, dy = y - s.mouse_y;
  s.mouse_x = x;
  s.mouse_y = y;
  int width = 0, height = 0;
  glfwGetWindowSize(w, &width, &height);
  if (height <= 0) return;
  if (s.left_down) s.draw->Orbit(dx / height, dy / height);
  if (s.right_down) s.draw->Zoom(dy / height);
}

void OnScroll(GLFWwindow* w, double /*dx*/, double dy) { StateOf(w).draw->Zoom(-0.05 * dy); }

}  // namespace

ViewerWindow::ViewerWindow(const CompiledModel& model, int width, int height, const std::string& title)
    : state_(std::make_unique<State>()) {
  state_->title = title;
  CheckImageSide("window width", width);
  CheckImageSide("window height", height);
  state_->window = std::make_unique<GlWindow>(width, height, true, title);
  state_->draw = std::make_unique<SceneDraw>(model, width, height);
  state_->draw->UseBuffer(mjFB_WINDOW);
  GLFWwindow* w = state_->window->get();
  glfwSetWindowUserPointer(w, state_.get());
  glfwSetKeyCallback(w, OnKey);
  glfwSetMouseButtonCallback(w, OnMouseButton);
  glfwSetCursorPosCallback(w, OnCursor);
  glfwSetScrollCallback(w, OnScroll);
  glfwSwapInterval(1);
}

ViewerWindow::~ViewerWindow() {
  state_->window->MakeCurrent();
  state_->draw.reset();
}

void ViewerWindow::Run(ViewSource& source, bool show_forces) {
  using Clock = std::chrono::steady_clock;
  State& s = *state_;
  GLFWwindow* w = s.window->get();
  if (show_forces != s.controls.show_forces()) s.controls.Apply(ViewerCommand::kToggleForces);
  s.draw->SetView(source.Camera());
  auto last = Clock::now();
  std::string shown_status;  // the source's status line in the title now
  while (!glfwWindowShouldClose(w) && !s.controls.quit()) {
    // Advance by the wall time since the last frame, then draw the state and the status.
    const auto now = Clock::now();
    s.controls.Advance(source, std::chrono::duration<double>(now - last).count());
    last = now;
    RenderOptions options;
    options.colours = source.Colours();
    options.contact_forces = s.controls.show_forces();
    options.force_scale_m_N = source.force_scale_m_N();
    mjrRect viewport{0, 0, 0, 0};
    glfwGetFramebufferSize(w, &viewport.width, &viewport.height);
    s.draw->Draw(source.sim(), options, viewport);
    const std::string status = source.Status();
    if (status != shown_status) {
      glfwSetWindowTitle(w, (status.empty() ? s.title : s.title + " - " + status).c_str());
      shown_status = status;
    }
    s.draw->Overlay(viewport, s.controls.Status(source.time()) + (status.empty() ? "" : "\n" + status));
    glfwSwapBuffers(w);
    glfwPollEvents();
  }
}

}  // namespace tactip
