#pragma once
// The clock of a run: physics steps and camera frames. The step may refine once, to the
// sliding step, from the gross-slip onset on; a step's time counts from that switch, and
// each camera frame falls on the step nearest its time.

namespace tactip {

/// Steps and frames of one run.
class StepClock {
 public:
  /// Steps of `timestep_s`, frames at `frame_rate_hz`.
  StepClock(double timestep_s, double frame_rate_hz);

  /// The time at which step n starts (after n steps).
  double StepTime(long long n) const;
  /// Steps taken, frames recorded.
  long long step() const { return step_; }
  long long frame() const { return frame_; }
  /// The step in force (s).
  double timestep_s() const { return dt_; }
  /// True when step n records a frame.
  bool FrameDue(long long n) const { return n == next_frame_step_; }
  /// One step taken.
  void Advance() { ++step_; }
  /// The frame due now is recorded: its time (s); the next frame is then due.
  double TakeFrame();
  /// From the next step on, steps of `fine_s` (once; ignored unless finer than the step).
  /// Returns true when the step changed.
  bool Refine(double fine_s);

 private:
  long long NextFrameStep() const;  // the step nearest frame frame_'s time, not before step_

  const double rate_hz_;
  double dt_;
  long long step_ = 0, frame_ = 0, next_frame_step_ = 0;
  long long switch_step_ = 0;  // the first step at the sliding step (0 before the switch)
  double switch_time_ = 0.0;   // the time at which it starts
  bool refined_ = false;
};

}  // namespace tactip
