#pragma once
// The viewer's playback: pause, single step, slow motion and the contact-force toggle, and
// how far the shown simulation advances in each displayed frame. No windowing here.

#include <string>

#include "sim/view_source.h"

namespace tactip {

/// What a key press asks the viewer to do.
enum class ViewerCommand {
  kPauseResume,   ///< space
  kSingleStep,    ///< right arrow or '.': one physics step while paused
  kSlower,        ///< '-': half the speed, down to kMinSpeed of real time
  kFaster,        ///< '+': double the speed, up to real time
  kToggleForces,  ///< 'f': contact force arrows on/off
  kQuit,          ///< Esc
};

/// Playback state of the viewer and the stepping it implies.
class ViewerControls {
 public:
  static constexpr double kMinSpeed = 1.0 / 64.0;  ///< slowest motion (fraction of real time)
  /// Longest wall time one frame accounts for (s): a frame that took longer (slow physics, a
  /// stalled window) does not make the next one try to catch up.
  static constexpr double kMaxFrameS = 1.0 / 30.0;

  /// Applies one command.
  void Apply(ViewerCommand command);
  /// Advances `source` for one displayed frame that followed `wall_dt_s` of wall time:
  /// while running, until its simulated time has gained min(wall_dt_s, kMaxFrameS) x speed()
  /// (a fraction of a step left over carries to the next frame); while paused, one step if
  /// one was asked for. Returns the number of steps taken.
  int Advance(ViewSource& source, double wall_dt_s);

  bool paused() const { return paused_; }
  /// Simulated seconds per wall-clock second: 1, 1/2, 1/4, ... kMinSpeed.
  double speed() const { return speed_; }
  bool show_forces() const { return show_forces_; }
  bool quit() const { return quit_; }
  /// True once the source said it has finished.
  bool finished() const { return finished_; }
  /// One status line: simulated time, speed, and paused / finished.
  std::string Status(double time_s) const;

 private:
  bool paused_ = false, step_requested_ = false, show_forces_ = false, quit_ = false, finished_ = false;
  double speed_ = 1.0;
  bool have_target_ = false;
  double target_s_ = 0.0;  // simulated time the source should reach
};

}  // namespace tactip
