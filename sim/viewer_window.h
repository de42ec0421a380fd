#pragma once
// The live viewer: a visible window showing a ViewSource as it steps, with mouse orbit and
// zoom and the keys of ViewerControls (space, right arrow or '.', '-', '+', 'f', Esc).

#include <memory>
#include <string>

#include "sim/view_source.h"

namespace tactip {

/// A window on one model's scene. Main thread only (GLFW's rule).
class ViewerWindow {
 public:
  /// Opens a visible `width` x `height` window for `model`; throws InputError when a side is
  /// out of range or no display is available. The model must outlive the window.
  ViewerWindow(const CompiledModel& model, int width, int height, const std::string& title);
  ~ViewerWindow();
  ViewerWindow(const ViewerWindow&) = delete;
  ViewerWindow& operator=(const ViewerWindow&) = delete;

  /// Shows `source` (a simulation of the window's model), stepping it in real time or
  /// slower, until Esc is pressed or the window is closed; contact forces are drawn from
  /// the start when `show_forces` is true ('f' toggles them). The source's status line is
  /// shown under the playback status and after the title.
  void Run(ViewSource& source, bool show_forces = false);

  /// Per-window input and drawing state (defined with the GLFW callbacks).
  struct State;

 private:
  std::unique_ptr<State> state_;
};

}  // namespace tactip
