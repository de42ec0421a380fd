#pragma once
// How well the blob pipeline (images.enabled) recovers the pins: its tracked positions
// (pins/detected_px) against the camera's noise-free projection of the true pin positions
// (pins/pos_m through the stored camera config), per run and sensor.

#include <string>
#include <vector>

#include "sensors/camera.h"
#include "sensors/dataset.h"

namespace tactip {

/// Detection error of one sensor over some frames.
struct TrackingFigures {
  std::string sensor;          ///< sensor name
  int run = -1;                ///< run index (-1: all runs together)
  long long samples = 0;       ///< (frame, pin) samples whose whole tip lies in the image
  long long out_of_view = 0;   ///< samples whose tip lies (partly) outside the image: not scored
  long long within_1px = 0;    ///< detected within 1 px of the projected truth
  long long misses = 0;        ///< detected_valid = 0
  double sum_sq_px2 = 0.0;     ///< sum of squared errors, px^2
  double max_px = 0.0;         ///< largest error, px
  long long camera_within_1px = 0;  ///< the camera model's pins/pos_px within 1 px, for comparison

  /// Fraction of samples within 1 px (NaN without samples).
  double WithinFraction() const;
  /// RMS error, px (NaN without samples).
  double RmsPx() const;
  /// Adds `other`'s counts into these.
  void Add(const TrackingFigures& other);
};

/// The figures of sensor `s` of run `run_index` seen by `camera` with tips of radius
/// `pin_tip_radius_mm` (only tips wholly inside the image are scored, TipInImage). Throws
/// InputError naming the file `path` if the sensor has no detected pins (no images).
TrackingFigures AnalyzeTracking(const SensorRecord& s, int run_index, const CameraConfig& camera,
                                double pin_tip_radius_mm, const std::string& path);

/// The report's table: one row per run and sensor, then one total row per sensor.
std::string FormatTrackingReport(const std::vector<TrackingFigures>& rows, const std::vector<TrackingFigures>& totals);

}  // namespace tactip
