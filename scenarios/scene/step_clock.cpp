#include "scenarios/scene/step_clock.h"

#include <algorithm>
#include <cmath>

#include "sensors/camera.h"

namespace tactip {

StepClock::StepClock(double timestep_s, double frame_rate_hz)
    : rate_hz_(frame_rate_hz), dt_(timestep_s), next_frame_step_(FrameStep(0, frame_rate_hz, timestep_s)) {}

double StepClock::StepTime(long long n) const { return switch_time_ + static_cast<double>(n - switch_step_) * dt_; }

double StepClock::TakeFrame() {
  const double tf = static_cast<double>(frame_) / rate_hz_;
  ++frame_;
  next_frame_step_ = NextFrameStep();
  return tf;
}

bool StepClock::Refine(double fine_s) {
  if (refined_ || fine_s >= dt_) return false;
  refined_ = true;
  // The step just taken ran at the old step: the next one starts where it ended.
  switch_time_ = StepTime(step_);
  switch_step_ = step_;
  dt_ = fine_s;
  next_frame_step_ = NextFrameStep();
  return true;
}

long long StepClock::NextFrameStep() const {
  if (!refined_) return FrameStep(frame_, rate_hz_, dt_);
  const double tf = static_cast<double>(frame_) / rate_hz_;
  return std::max(step_, switch_step_ + std::llround((tf - switch_time_) / dt_));
}

}  // namespace tactip
