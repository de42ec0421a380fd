#pragma once
// Limits of a physically possible state of a tactile sensor in a run. A pin marker a dome
// radius away from where it rests, or a pin (or the whole skin) pressed far harder than the
// press and the load it carries can press it, means the solver has diverged without MuJoCo
// noticing (no warning fires, e.g. with too few solver iterations while the contact changes
// fast); the run stops rather than record such a state as data.

#include <string>
#include <vector>

#include "models/skin.h"

namespace tactip {

/// Bounds of a physically possible frame of one sensor's skin.
struct StateLimits {
  /// How far beyond the most a static press allows a state may go before it is absurd.
  static constexpr double kAbsurdFactor = 2.0;
  double max_marker_shift_m = 0.0;  ///< a pin marker's distance from its rest position: the dome's outer radius
  double max_pin_force_N = 0.0;     ///< normal force on one pin
  double max_total_force_N = 0.0;   ///< sum of the pins' normal forces

  /// The limits of a `skin` pressed at most `deepest_press_mm` (negative: no press) plus
  /// `extra_press_m` (a controller that presses deeper than its protocol, such as a catch),
  /// carrying `load_N` (the object's weight and what else loads the contact), with
  /// `n_collidable` pins that can touch. A pin pressed by the deepest press plus 1 mm, with
  /// every neighbour in antiphase, carries at most (k_normal + 12 k_bend) times that; add the
  /// load, for one pin or for every pin that can touch, and allow kAbsurdFactor on top.
  static StateLimits For(const SkinConfig& skin, double deepest_press_mm, double load_N, int n_collidable,
                         double extra_press_m = 0.0);
};

/// "" when a frame is within `limits`, else what is beyond them (one line). Per pin:
/// `marker_shift_m` its marker's distance from its rest position, `normal_N` its contact's
/// normal force.
std::string ImplausibleState(const StateLimits& limits, const std::vector<double>& marker_shift_m,
                             const std::vector<double>& normal_N);

}  // namespace tactip
