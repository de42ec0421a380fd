#pragma once
// Incipient-slip measures of one recorded run shared by `tactip report incipient` and
// `tactip report signatures`: when the bulk-subtraction detector first alarms, and how
// closely the internal pins track the external markers.

#include <cstddef>
#include <limits>
#include <vector>

#include "detectors/incipient.h"
#include "sensors/dataset.h"

namespace tactip {

/// The first alarm of the incipient detector in a recorded run.
struct IncipientAlarm {
  double time_s = std::numeric_limits<double>::quiet_NaN();  ///< NaN when it never alarms
  size_t frame = 0;  ///< the alarm's frame; 0 also without one, so check time_s first
  std::vector<int> pins;  ///< the detector's slipping set at the alarm, ascending (empty without one)
};

/// The first alarm of a fresh IncipientDetector(params) fed sensor's frames from frame
/// `from_frame` on. Throws InputError for bad params.
IncipientAlarm FirstIncipientAlarm(const RunRecord& run, const SensorRecord& sensor, const IncipientParams& params,
                                   size_t from_frame);

/// Agreement of internal pin and external marker displacements.
struct MarkerTracking {
  double correlation = 0.0;  ///< Pearson correlation of the displacement components
  double error = 0.0;        ///< relative RMS difference |d_in - d_ext| / |d_ext|
};

/// How long after the fall (s) the tracking window runs: the gross-slip release.
constexpr double kTrackingAfterFallS = 0.3;

/// Internal vs external displacements (sensor y and z, metres, no mirroring) since the
/// retraction started (frame 0 without retract_start_s), of the pins in contact then, up
/// to kTrackingAfterFallS after the fall (the run's end without object_fall_s). NaN
/// figures without external markers or without variation.
MarkerTracking TrackMarkers(const RunRecord& run, const SensorRecord& sensor);

}  // namespace tactip
