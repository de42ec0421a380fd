#include "sim/viewer_controls.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace tactip {

void ViewerControls::Apply(ViewerCommand command) {
  switch (command) {
    case ViewerCommand::kPauseResume:
      paused_ = !paused_;
      have_target_ = false;  // resume from where the source is, not from where it was
      break;
    case ViewerCommand::kSingleStep:
      if (paused_) step_requested_ = true;
      break;
    case ViewerCommand::kSlower: speed_ = std::max(kMinSpeed, speed_ / 2.0); break;
    case ViewerCommand::kFaster: speed_ = std::min(1.0, speed_ * 2.0); break;
    case ViewerCommand::kToggleForces: show_forces_ = !show_forces_; break;
    case ViewerCommand::kQuit: quit_ = true; break;
  }
}

int ViewerControls::Advance(ViewSource& source, double wall_dt_s) {
  if (finished_) return 0;
  // Paused: at most the one step asked for.
  if (paused_) {
    if (!step_requested_) return 0;
    step_requested_ = false;
    finished_ = !source.Step();
    return finished_ ? 0 : 1;
  }
  // Running: step until the source reaches the frame's target time.
  if (!have_target_) {
    target_s_ = source.time();
    have_target_ = true;
  }
  target_s_ += std::clamp(wall_dt_s, 0.0, kMaxFrameS) * speed_;
  int steps = 0;
  while (source.time() < target_s_) {
    if (!source.Step()) {
      finished_ = true;
      break;
    }
    ++steps;
  }
  return steps;
}

std::string ViewerControls::Status(double time_s) const {
  const std::string speed = speed_ >= 1.0 ? "real time" : fmt::format("1/{:g} of real time", std::round(1.0 / speed_));
  std::string state = finished_ ? "  finished" : (paused_ ? "  PAUSED (space: resume, right arrow: step)" : "");
  return fmt::format("t = {:.3f} s   {}{}{}", time_s, speed, show_forces_ ? "   forces" : "", state);
}

}  // namespace tactip
