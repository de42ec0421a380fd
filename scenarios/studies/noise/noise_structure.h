#pragma once
// The structure of a run's static pin noise, as measured on a real TacTip's still frames
// (real-sensor figures in docs/validation.md#pin-noise): how much of each pin's scatter is the
// whole pattern moving together (a translation, a similarity per frame), what is left and how
// it correlates between neighbours, how slowly the common part varies, and the static pin
// speed at W = 1 and W = 5. MuJoCo-free: reads a RunRecord.

#include <string>
#include <vector>

#include "sensors/dataset.h"

namespace tactip {

/// Which frames count as still: the held window before the retraction (or before the onset,
/// scenarios/studies/signatures/held_noise.h), or every frame of a recording without either.
struct NoiseWindow {
  size_t first = 0, end = 0;  ///< frames [first, end)
  bool held = false;          ///< true: the held window; false: the whole run
};
NoiseWindow StillFrames(const RunRecord& run, double held_window_s);

/// The figures of one sensor's still frames, each pin's straight line over the window taken
/// out first (a held skin still settles slowly); NaN where there are too few frames or pins.
struct NoiseStructure {
  int run = 0;
  std::string sensor;
  bool held = false;                     ///< the window was the held one
  int frames = 0, pins = 0;              ///< frames of the window; pins valid in all of them
  double pattern_radius_px = 0.0;        ///< the outer ring's mean distance from the pattern's centre
  double pin_std_px = 0.0;               ///< per-pin position std per coordinate (RMS over pins)
  double common_std_px = 0.0;            ///< std per coordinate of the mean over the pins
  double common_ratio = 0.0;             ///< common_std_px / (pin_std_px / sqrt(pins))
  double translation_share = 0.0;        ///< share of per-pin variance one translation per frame removes
  double similarity_share = 0.0;         ///< ... one similarity (translation, rotation, scale) per frame
  double residual_std_px = 0.0;          ///< what is left, per coordinate
  double neighbour_corr = 0.0;           ///< residual correlation of pins up to 1.3 pitches apart
  double next_corr = 0.0;                ///< ... 1.3 to 2.3 pitches apart
  double common_lag1 = 0.0;              ///< lag-1 autocorrelation of the common mode
  double consecutive_over_random = 0.0;  ///< mean |step| between consecutive frames / between any two frames
  double speed_w1_px = 0.0;              ///< mean pin speed, unsmoothed, px/frame
  double speed_w5_px = 0.0;              ///< ... with the 5-frame moving average
};

/// Measures NoiseStructure on `sensor`'s frames in `window`.
NoiseStructure MeasureNoiseStructure(const RunRecord& run, const SensorRecord& sensor, const NoiseWindow& window,
                                     int run_index);

/// The table: one row per run and sensor, the mean over them, and the real TacTip's figures
/// beside with whether the mean is within a factor 1.5 of the real range.
std::string FormatNoiseReport(const std::vector<NoiseStructure>& rows);
/// The rows as CSV (header first).
std::string NoiseCsv(const std::vector<NoiseStructure>& rows);

}  // namespace tactip
