#pragma once
// A GLFW window with its OpenGL context: hidden for offscreen rendering, visible for the
// live viewer. Internal to sim/ (the renderer and the viewer window).

#include <string>

struct GLFWwindow;

namespace tactip {

/// One GLFW window and its OpenGL context. GLFW is initialised while any window exists.
/// Use from the main thread only (GLFW's rule).
class GlWindow {
 public:
  /// Opens a `width` x `height` window (hidden unless `visible`); throws InputError when no
  /// X display can be opened ("no display: run under xvfb-run or set DISPLAY") or it has no
  /// OpenGL.
  GlWindow(int width, int height, bool visible, const std::string& title);
  ~GlWindow();
  GlWindow(const GlWindow&) = delete;
  GlWindow& operator=(const GlWindow&) = delete;

  /// Makes this window's OpenGL context the current one of the calling thread.
  void MakeCurrent() const;
  /// The GLFW handle (owned by this object).
  GLFWwindow* get() const { return window_; }

 private:
  GLFWwindow* window_ = nullptr;
};

}  // namespace tactip
