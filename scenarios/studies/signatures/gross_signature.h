#pragma once
// The hardware's gross-slip signature of one run (real-sensor.md section 2): how long the
// mean pin speed stays above the camera noise from the onset, its peak, how co-linear the
// moving pins are at and after the onset, when the object loses contact, and how far the
// pattern steps and whether it is still afterwards ("a step change, then flat").

#include <optional>

#include "scenarios/studies/signatures/held_noise.h"
#include "sensors/dataset.h"

namespace tactip {

/// Frames after the onset frame at which the co-linearity is measured again ("a few frames
/// after onset": messy on the hardware).
constexpr int kColinearLaterFrames = 5;
/// Half-angle of the cone around the mean direction within which a pin counts as
/// co-linear, degrees.
constexpr double kColinearHalfAngleDeg = 30.0;
/// How long after the onset the spike peak is searched (s).
constexpr double kSpikePeakSpanS = 0.3;

/// Frames before the onset frame over which the loaded pattern's position is averaged.
constexpr int kStepBeforeFrames = 10;
/// Frames after the onset frame, [first, end), over which the released pattern's position
/// (and its leftover speed) is averaged: after the hardware's ~20-frame spike.
constexpr int kStepAfterFirstFrame = 20;
constexpr int kStepAfterEndFrame = 30;

/// Gross-slip figures of a run with a gross_slip_onset_s. A figure is NaN when its event
/// did not happen (no frame with moving pins; contact never lost in the recording).
struct GrossSignature {
  HeldNoise noise;              ///< camera noise while held, sets the thresholds
  int onset_frame = 0;          ///< first frame at or after the onset (at least 1)
  /// Where the spike starts: the onset frame if its unsmoothed mean pin speed exceeds
  /// noise.Level(), else the next frame (the onset frame's velocity spans the onset, part
  /// of it still static).
  int spike_start_frame = 0;
  /// Consecutive frames from spike_start_frame whose unsmoothed mean pin speed exceeds
  /// noise.Level(); -1 when the noise could not be measured.
  int spike_width_frames = 0;
  double spike_peak_px = 0.0;     ///< peak unsmoothed mean pin speed within kSpikePeakSpanS, px/frame
  double spike_peak_w5_px = 0.0;  ///< the same with a kSmoothingFrames moving average, px/frame
  /// Share of the moving pins (speed > noise.PinLevel()) whose velocity lies within
  /// kColinearHalfAngleDeg of their mean velocity's direction, at spike_start_frame.
  double colinear_onset = 0.0;
  double colinear_later = 0.0;  ///< the same kColinearLaterFrames frames later
  /// Time of the first frame at or after the onset frame with no pin in contact, minus the
  /// onset time, s.
  double contact_lost_s = 0.0;
  /// The pattern's step at gross slip: length of the pins' mean displacement from their mean
  /// positions over the kStepBeforeFrames frames before the onset frame to their mean
  /// positions over frames [onset + kStepAfterFirstFrame, onset + kStepAfterEndFrame), px
  /// (pins valid in both windows); NaN when either window is not in the recording.
  double step_px = 0.0;
  /// Mean of the W5 mean pin speed over that later window, px/frame ("then flat" when it is
  /// near noise.mean_speed_w5_px); NaN when the window is not in the recording.
  double after_w5_px = 0.0;
};

/// Measures the signature of sensor's recording of `run`, the noise over the still window
/// of `held_window_s` (MeasureHeldNoise); nullopt when the run has no gross-slip onset
/// (the figures do not apply).
std::optional<GrossSignature> MeasureGrossSignature(const RunRecord& run, const SensorRecord& sensor,
                                                    double held_window_s = kHeldWindowS);

/// The co-linear share at frame f for pins faster than `pin_level_px` (px/frame); NaN when
/// no pin moves or their velocities cancel.
double ColinearFraction(const SensorRecord& sensor, size_t f, double pin_level_px);

}  // namespace tactip
