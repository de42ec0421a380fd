#pragma once
// The camera noise of a run measured while the object is held still: the level a pin
// speed must exceed to count as motion in the signature figures.

#include "sensors/dataset.h"

namespace tactip {

/// Longest still window (s): the rail protocol's default hold (rail.hold_s = 0.5 s)
/// between the lift and the retraction.
constexpr double kHeldWindowS = 0.5;
/// Without retract_start_s the window ends this long before the gross-slip onset (s).
constexpr double kHeldGapBeforeOnsetS = 0.1;
/// Moving-average length of the smoothed figures: the hardware detector's W (frames).
constexpr int kSmoothingFrames = 5;
/// Standard deviations above the mean that a speed must exceed to be above the noise.
constexpr double kNoiseSigmas = 3.0;

/// Statistics of the pin speeds in the held window, px/frame; NaN when the window has
/// fewer than two frames with pin velocities.
struct HeldNoise {
  int frames = 0;                ///< frames in the window with pin velocities
  double mean_speed_px = 0.0;    ///< mean over the window of the unsmoothed mean pin speed
  double std_speed_px = 0.0;     ///< its standard deviation over the window's frames
  double mean_speed_w5_px = 0.0; ///< mean of the mean pin speed with a 5-frame moving average
  double pin_mean_px = 0.0;      ///< mean of single pins' unsmoothed speeds (all pin-frames)
  double pin_std_px = 0.0;       ///< their standard deviation

  /// Noise level of the mean pin speed: mean + kNoiseSigmas std, px/frame.
  double Level() const { return mean_speed_px + kNoiseSigmas * std_speed_px; }
  /// Noise level of one pin's speed: pin mean + kNoiseSigmas pin std, px/frame.
  double PinLevel() const { return pin_mean_px + kNoiseSigmas * pin_std_px; }
};

/// The still window of a dataset's runs: its config's rail.hold_s (root attribute
/// config_yaml) if shorter than kHeldWindowS, else kHeldWindowS (also when the config has
/// no readable rail.hold_s), s.
double HeldWindowS(const DatasetHeader& header);

/// Measures HeldNoise over the `window_s` before retract_start_s (or, without it, before
/// gross_slip_onset_s - kHeldGapBeforeOnsetS); all NaN when the run has neither.
HeldNoise MeasureHeldNoise(const RunRecord& run, const SensorRecord& sensor, double window_s = kHeldWindowS);

}  // namespace tactip
