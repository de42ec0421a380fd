#pragma once
// Run health: figures measured while a rail run runs that say whether its ground truth can
// be trusted, and the thresholds that flag it (the `health.` section). A run over any
// threshold is written with health_ok = 0 and the reason, never silently as good data.

#include <cstdint>
#include <string>
#include <vector>

#include "sim/config.h"

namespace tactip {

/// Thresholds of run health (the `health.` section).
struct HealthConfig {
  int max_flicker = 2;                 ///< contact on/off transitions of any pin while held
  double max_pin_speed_px = 0.2;       ///< noise-free pin speed while held and nothing slips, beyond the sensor's motion, px/frame
  double max_stick_creep_um = 20.0;    ///< object sliding on the centre pin before any pin slips, um
  double max_energy_gain = 0.02;       ///< energy created by the integration while held, per stored energy

  template <class V>
  void Visit(V& v) {
    v("max_flicker", max_flicker, "",
      "Contact on/off transitions of any one pin while the object is held (lift end to gross slip). A pin "
      "that leaves the contact once makes 1, one that touches again 2; more is a pin chattering in and out "
      "of contact.",
      Bounds::Closed(0, 100000));
    v("max_pin_speed_px", max_pin_speed_px, "px/frame",
      "Largest noise-free pin speed while the object is held and no pin slips, beyond what the sensor's own "
      "motion explains (a pin pushed quasi-statically moves at most as far as the sensor moves against the "
      "object: the camera's largest image gain times the sensor's displacement over the frame). A quasi-static "
      "hold moves pins by far less than the camera noise (0.5 px/frame); above this a detector would see "
      "motion that is not slip (the incipient detector's s_thr is 0.2).",
      Bounds::Closed(0.0, 1000.0));
    v("max_stick_creep_um", max_stick_creep_um, "um",
      "Sliding of the object relative to the centre pin's contact point from the start of retraction until "
      "the first pin slips. Sticking contacts give only their elastic pre-sliding (contact.presliding_mm).",
      Bounds::Closed(0.0, 1e6));
    v("max_energy_gain", max_energy_gain, "",
      "Mechanical energy created by the time integration while the object is held (energy change minus the "
      "work of actuators, damping and constraints, summed where positive), as a fraction of the elastic "
      "energy stored in the skin. Chattering contacts and unstable modes create 0.05 and more; a healthy "
      "step's first-order error while the skin unloads stays below 0.02 (0.0006 at the 1 mm/s retraction, "
      "0.017 at 50 mm/s, with the onset on its Coulomb prediction).",
      Bounds::Closed(0.0, 1e6));
  }
  void ValidateRules() const {}
};

/// The figures of one run and the verdict.
struct RunHealth {
  int flicker_max = 0;          ///< most contact on/off transitions of one pin while held
  int flicker_pin = -1;         ///< that pin
  double pin_speed_px = 0.0;    ///< largest noise-free pin speed while held and nothing slips, beyond the sensor's motion, px/frame
  double stick_creep_um = 0.0;  ///< object sliding on the centre pin before any pin slips, um
  double energy_gain = 0.0;     ///< energy created while held, per stored elastic energy
  bool ok = true;               ///< every figure within its threshold
  std::string reason;           ///< what is over its threshold ("" when ok)
};

/// Collects the health figures of one run frame by frame and step by step.
class RunHealthMonitor {
 public:
  RunHealthMonitor(int n_pins, const HealthConfig& cfg);

  /// One camera frame. `held`: between the lift's end and gross slip. `clean_px` (N x 2)
  /// are the pin image positions before camera noise; `creep_m` is the object's position
  /// relative to the centre pin's contact point along the rail (from the retraction on,
  /// NaN before); `any_slip` whether some pin slips in this frame; `quasi_static_px` the
  /// largest image motion the sensor's own motion since the last frame explains.
  void Frame(bool held, bool retracting, const float* clean_px, const std::uint8_t* pin_contact, bool any_slip,
             double creep_m, double quasi_static_px = 0.0);
  /// One physics step while held: energy created by the step (may be negative) and the
  /// elastic energy stored at its start.
  void Step(double created_J, double stored_J);
  /// The figures and the verdict.
  RunHealth Result() const;

 private:
  HealthConfig cfg_;
  int n_;
  std::vector<float> prev_px_;
  std::vector<std::uint8_t> prev_contact_;
  std::vector<int> transitions_;
  bool have_prev_ = false, slipped_ = false;
  double pin_speed_px_ = 0.0, creep_ref_m_, creep_max_m_ = 0.0;
  double created_J_ = 0.0, stored_max_J_ = 0.0;
};

}  // namespace tactip
