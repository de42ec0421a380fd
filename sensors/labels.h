#pragma once
// Ground-truth labels from the simulated contact state: per-pin contact and
// stick/slip, per-frame gross slip, and the run-level events.

#include <cstdint>
#include <vector>

#include "sim/config.h"

namespace tactip {

/// Label tolerances (the `labels.` section).
struct LabelConfig {
  double slip_speed_m_s = 1e-5;     ///< a contacting pin slips above this tangential speed...
  double cone_fraction = 0.98;      ///< ...while its friction force is on the cone (|f_t| >= this * mu f_n)
  double fall_threshold_mm = 1.0;   ///< object slip: drop relative to the sensor beyond this

  template <class V>
  void Visit(V& v) {
    v("slip_speed_m_s", slip_speed_m_s, "m/s",
      "A contacting pin is labelled slipping when the tangential speed of the stimulus relative to it exceeds "
      "this (and its force is on the friction cone). Stuck contacts move < 1e-7 m/s with the noslip pass; a "
      "sliding object reaches 1e-5 m/s within a few ms of the Coulomb threshold. Onsets agree within a frame "
      "over 1e-6 .. 1e-4 and per-pin labels over 1e-5 .. 1e-4; below ~1e-6 saturated edge pins with tiny "
      "normal force show MuJoCo's residual creep.",
      Bounds::Closed(1e-7, 1e-1));
    v("cone_fraction", cone_fraction, "",
      "A sliding pin's friction force also sits on the Coulomb cone: |f_t| >= cone_fraction * mu * f_n. This "
      "separates Coulomb sliding from MuJoCo's velocity-level contact compliance (stuck pins briefly move "
      "~0.3 mm/s relative to the object while their load changes fast, at forces far inside the cone).",
      Bounds::LeftOpen(0.0, 1.0));
    v("fall_threshold_mm", fall_threshold_mm, "mm",
      "Object slip / fall: the object has dropped this far relative to the sensor (what an external marker "
      "tracker would see).",
      Bounds::Closed(0.01, 20.0));
  }
  void ValidateRules() const {}
};

/// Per-pin contact sample in one frame.
struct PinContactSample {
  bool in_contact = false;
  double slip_speed_m_s = 0.0;   ///< tangential speed of the stimulus relative to the pin
  double cone_use = 0.0;         ///< |f_t| / (mu f_n): 1 on the friction cone
};

/// Labels of one frame.
struct FrameLabels {
  int n_contact = 0;  ///< pins touching the stimulus
  int n_slip = 0;     ///< contacting pins that slide
  /// 1 when every contacting pin slides (gross slip), else 0.
  std::uint8_t gross_slip = 0;
};

/// Fills pin_contact / pin_slip (N each) and returns the frame label.
FrameLabels LabelFrame(const std::vector<PinContactSample>& pins, const LabelConfig& cfg,
                       std::uint8_t* pin_contact, std::uint8_t* pin_slip);

}  // namespace tactip
