#pragma once
// The hardware's online incipient-slip detection on the transparent-acrylic rig: after the
// lift the arm retracts in small steps (0.2 mm by default), pausing after each while the
// incipient detector (bulk subtraction) reads every frame, and stops for good when it fires.
// Success: stopped before the object slips grossly / falls.

#include <limits>
#include <string>
#include <vector>

#include "detectors/incipient.h"
#include "scenarios/rail/rail_controller.h"

namespace tactip {

/// The closed loop's settings (command-line options of `tactip run incipient-stop`).
struct StopOptions {
  double step_mm = 0.2;            ///< retraction per step
  double pause_s = 0.3;            ///< still time after each step
  double hold_s = 2.0;             ///< after the stop: how long the trial watches the object
  std::string markers = "internal";  ///< which markers the detector reads: internal or external
  IncipientParams detector;        ///< W, s_thr, I_thr (hardware values)

  /// Throws InputError naming the option and its allowed range.
  void Validate() const;
};

/// Step-wise retraction that stops when the incipient detector fires. One per run.
class StopController : public RailController {
 public:
  /// Steps move at the schedule's retraction speed.
  StopController(const RailSchedule& schedule, const StopOptions& options);

  ArmTargets Targets(double t) override;
  void OnFrame(const FrameInput& input) override;
  bool Done(double t) const override;
  double GiveUpTime(const RailSchedule& schedule) const override;
  std::vector<ControllerAction> Actions() const override;

 private:
  double StepX(double t) const;  // the step-wise retraction's target at t
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  const RailSchedule schedule_;
  const StopOptions options_;
  const double step_m_, move_s_, period_s_;
  IncipientDetector detector_;
  double stop_s_ = kNaN, x_stop_m_ = 0.0;
};

}  // namespace tactip
