#pragma once
// The hardware's incipient-slip signature of one run (real-sensor.md section 3): when the
// partial slip becomes visible to the camera, how strong it is, when the hardware
// detector alarms, where slip starts, and how internal and external markers agree.

#include <optional>
#include <string>

#include "detectors/incipient.h"
#include "scenarios/studies/signatures/slip_sectors.h"
#include "sensors/dataset.h"

namespace tactip {

/// The pins of the detector's slipping set at its first alarm, by their ground-truth labels
/// in that frame: does the alarm come from the slipping pins? (All 0 without an alarm.)
struct AlarmPins {
  int slipping = 0;  ///< in contact and labelled sliding
  int stuck = 0;     ///< in contact and sticking
  int free = 0;      ///< out of contact
  int total() const { return slipping + stuck + free; }
  AlarmPins& operator+=(const AlarmPins& o) {
    slipping += o.slipping;
    stuck += o.stuck;
    free += o.free;
    return *this;
  }
};

/// Incipient figures of a fingerprint-skin run with a fall or an incipient onset. The
/// incipient window runs from the retraction start to the gross-slip onset (the fall
/// without one). Times in s, speeds in px/frame; NaN = the event did not happen.
struct IncipientSignature {
  bool has_phase = false;      ///< the run has a ground-truth incipient_onset_s
  bool has_external = false;   ///< the sensor has external markers
  /// First frame of the window from which, for params.window consecutive frames, the
  /// labelled-slipping pins' mean smoothed speed (window params.window) exceeds that of
  /// the other pins (the bulk) by params.speed_thr_px.
  double visible_s = 0.0;
  double visible_lead_s = 0.0;  ///< object_fall_s - visible_s
  /// How far the run is from (or past) visibility: the largest excess of the slipping pins'
  /// smoothed speed over the bulk's that lasts params.window consecutive frames, px/frame
  /// (visible exactly when it passes params.speed_thr_px); NaN if no pin slips that long.
  double sustained_excess_px = 0.0;
  /// The same for one pin at a time: the largest, over the pins, of the excess of a pin's
  /// smoothed speed over the bulk's that lasts params.window consecutive frames on which it
  /// is labelled slipping, px/frame (NaN if no pin slips that long). Says whether the mean
  /// over the slipping pins hides a few that the camera would see.
  double pin_sustained_excess_px = 0.0;
  /// Peak over the window of the labelled-slipping pins' mean speed, unsmoothed (W = 1)
  /// and with a 5-frame moving average (W = 5); NaN without a phase.
  double amplitude_w1_px = 0.0;
  double amplitude_w5_px = 0.0;
  double alarm_s = 0.0;         ///< first alarm of the detector (params) fed from the retraction start
  double alarm_lead_s = 0.0;    ///< object_fall_s - alarm_s
  AlarmPins alarm_pins;         ///< the labels of the pins that raised that alarm
  /// The camera's first-moving sector: the sector(s) holding most of the detector's slipping
  /// set at that alarm (MostCommonSector; "" without an alarm).
  std::string alarm_sector;
  SectorOrder sectors;          ///< first-slipping sector and the order, within the window
  double tracking_correlation = 0.0;  ///< internal vs external displacements (TrackMarkers)
};

/// Measures the signature with the detector parameters `params` (the hardware's by
/// default); nullopt when it does not apply: a smooth skin (sensor attribute skin_pattern
/// not fingerprint-*) or neither object_fall_s nor incipient_onset_s. Throws InputError for
/// bad params. The sectors are ordered by the pins' first slipping physics steps when the
/// sensor recorded them (labels/pin_first_slip_s), unless `sectors_by_frame`, and by the
/// frames' labels otherwise.
std::optional<IncipientSignature> MeasureIncipientSignature(const RunRecord& run, const SensorRecord& sensor,
                                                            const IncipientParams& params = {},
                                                            bool sectors_by_frame = false);

}  // namespace tactip
