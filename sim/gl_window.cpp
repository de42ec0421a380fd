#include "sim/gl_window.h"

#include <GLFW/glfw3.h>

#include <cstdlib>

#include <fmt/format.h>

#include "sim/config.h"

namespace tactip {

namespace {

// GLFW is initialised once for all windows and terminated with the last one; the count
// must be shared by every window of the process, so it is a function-local static
// (GLFW itself is process-global and main-thread only).
int& OpenWindows() {
  static int count = 0;
  return count;
}

// GLFW's description of its last error ("" if none).
std::string LastGlfwError() {
  const char* description = nullptr;
  glfwGetError(&description);
  return description ? description : "";
}

// Initialises GLFW for the first window; throws InputError naming the display problem.
void AcquireGlfw() {
  if (OpenWindows() == 0 && glfwInit() != GLFW_TRUE) {
    const char* display = std::getenv("DISPLAY");
    if (display == nullptr || *display == '\0') throw InputError("no display: run under xvfb-run or set DISPLAY");
    throw InputError(fmt::format("no display: cannot open DISPLAY={} ({}); run under xvfb-run or set DISPLAY",
                                 display, LastGlfwError()));
  }
  ++OpenWindows();
}

void ReleaseGlfw() {
  if (--OpenWindows() == 0) glfwTerminate();
}

}  // namespace

GlWindow::GlWindow(int width, int height, bool visible, const std::string& title) {
  AcquireGlfw();
  // MuJoCo's renderer needs a compatibility-profile context (the default one).
  glfwDefaultWindowHints();
  glfwWindowHint(GLFW_VISIBLE, visible ? GLFW_TRUE : GLFW_FALSE);
  glfwWindowHint(GLFW_DOUBLEBUFFER, visible ? GLFW_TRUE : GLFW_FALSE);
  window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (window_ == nullptr) {
    const std::string why = LastGlfwError();
    ReleaseGlfw();
    throw InputError(fmt::format("cannot open an OpenGL window on DISPLAY={} ({})",
                                 std::getenv("DISPLAY") ? std::getenv("DISPLAY") : "", why));
  }
  MakeCurrent();
}

GlWindow::~GlWindow() {
  glfwDestroyWindow(window_);
  ReleaseGlfw();
}

void GlWindow::MakeCurrent() const { glfwMakeContextCurrent(window_); }

}  // namespace tactip
