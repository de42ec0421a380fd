#pragma once
// The hardware's online slip detection and grasp recovery on the rail rig: while the arm
// retracts, a trained detector reads every camera frame; when the response strategy fires
// (two consecutive slip frames by default), the arm, after the loop's latency, moves back in
// along the stimulus normal to catch the object.

#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "detectors/detector.h"
#include "detectors/response.h"
#include "models/rail_rig.h"
#include "scenarios/rail/rail_controller.h"

namespace tactip {

/// The closed loop's settings (command-line options of `tactip run rail-catch`).
struct CatchOptions {
  std::string response = "2Fr1Sen";  ///< response strategy: NFr consecutive slip frames on NSen sensors
  double classify_ms = 3.0;          ///< classification time per frame (hardware: 3 ms)
  double arm_response_ms = 10.0;     ///< from the command to the arm moving
  double catch_speed_mm_s = 50.0;    ///< speed of the arm moving back in
  double catch_extra_mm = 0.0;       ///< how far past the press depth the arm moves back in
  double hold_s = 0.5;               ///< after the arm is back in: how long the trial watches the object

  /// Throws InputError naming the option and its allowed range.
  void Validate() const;
  /// Throws InputError unless the catch stays within the press a TacTip tolerates: the
  /// protocol's deepest press (rail.press_depth_mm + rail.press_depth_jitter_mm) plus
  /// catch_extra_mm at most RailConfig::kMaxPressDepthMm.
  void ValidateFor(const RailConfig& rail) const;
};

/// The rail protocol with a detector in the loop. One instance per run.
class CatchController : public RailController {
 public:
  /// `detector` reads the frames of the run's one sensor (it is Reset here); the arm follows
  /// `schedule` until the strategy fires after the retraction has started.
  CatchController(const RailSchedule& schedule, std::unique_ptr<Detector> detector, const CatchOptions& options);

  ArmTargets Targets(double t) override;
  void OnFrame(const FrameInput& input) override;
  bool Done(double t) const override;
  /// The catch presses catch_extra_mm past the press depth.
  double ExtraPressM() const override { return options_.catch_extra_mm * 1e-3; }
  std::vector<ControllerAction> Actions() const override;
  /// classify_us: the measured wall time per Detector::Update (mean, microseconds).
  std::map<std::string, double> Figures() const override;

  /// When slip was declared (frame time) and when the arm started back in (NaN: not yet).
  double declared_s() const { return declared_s_; }
  double act_s() const { return act_s_; }

 private:
  double CatchX() const;  // where the arm moves back in to (m)
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  const RailSchedule schedule_;
  std::unique_ptr<Detector> detector_;
  ResponseStrategy response_;
  const CatchOptions options_;
  double declared_s_ = kNaN, act_s_ = kNaN, x_act_m_ = 0.0, back_in_s_ = kNaN;
  double classify_wall_s_ = 0.0;
  long frames_ = 0;
};

}  // namespace tactip
