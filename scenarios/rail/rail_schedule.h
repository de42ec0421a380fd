#pragma once
// Timeline of one rail run: press, settle, lift, hold, retract (seconds, metres).

#include <algorithm>

#include "models/rail_rig.h"

namespace tactip {

/// Quintic smooth step: 0 -> 1 with zero velocity and acceleration at both ends.
inline double SmoothStep(double u) {
  u = std::clamp(u, 0.0, 1.0);
  return u * u * u * (10.0 + u * (-15.0 + 6.0 * u));
}

/// When each phase of the protocol starts and ends, and the arm servo targets.
struct RailSchedule {
  static constexpr double kExtraRetractM = 5e-3;  ///< keep retracting this far past the press before giving up
  double press_start, press_end, lift_start, lift_end, retract_start, give_up;
  double press_dist, lift_dist, retract_speed;

  /// The timeline for a press of `depth_m` and a retraction at `retract_speed_mm_s` under the
  /// protocol settings `r`.
  RailSchedule(const RailConfig& r, double depth_m, double retract_speed_mm_s) {
    press_dist = r.approach_gap_mm * 1e-3 + depth_m;
    lift_dist = r.lift_mm * 1e-3;
    retract_speed = retract_speed_mm_s * 1e-3;
    press_start = r.settle_s;
    press_end = press_start + press_dist / (r.press_speed_mm_s * 1e-3);
    lift_start = press_end + r.settle_s;
    lift_end = lift_start + lift_dist / (r.lift_speed_mm_s * 1e-3);
    retract_start = lift_end + r.hold_s;
    give_up = retract_start + (press_dist + kExtraRetractM) / retract_speed;
  }
  /// Servo target of the normal (x) axis at time t, metres.
  double X(double t) const {
    const double pressed = press_dist * SmoothStep((t - press_start) / (press_end - press_start));
    return pressed - retract_speed * std::max(0.0, t - retract_start);
  }
  /// Servo target of the vertical (z) axis at time t, metres.
  double Z(double t) const { return lift_dist * SmoothStep((t - lift_start) / (lift_end - lift_start)); }
};

}  // namespace tactip
