#pragma once
// Incipient-slip analysis of simulated runs: ground-truth lead times, which pins slip
// first, how closely internal pins track external markers, and what the bulk-
// subtraction incipient detector sees. Used by `tactip report incipient` and by sweeps.

#include <string>
#include <vector>

#include "detectors/incipient.h"
#include "scenarios/studies/signatures/slip_sectors.h"
#include "sensors/dataset.h"

namespace tactip {

/// Per-run incipient-slip figures (NaN where an event did not happen).
struct IncipientRunMetrics {
  int run = 0;
  double retract_start_s = 0.0;
  double incipient_onset_s = 0.0;   ///< ground truth: first partial-slip frame after retraction starts
  double gross_onset_s = 0.0;       ///< ground truth: all contacting pins slide and the object moves
  double fall_s = 0.0;              ///< object dropped labels.fall_threshold_mm relative to the sensor
  double lead_gross_s = 0.0;        ///< gross_onset_s - incipient_onset_s
  double lead_fall_s = 0.0;         ///< fall_s - incipient_onset_s
  double pre_slip_fraction = 0.0;   ///< contacting pins that slid before gross slip
  /// Mean distance from the axis of the pins slipping at the incipient onset over that of
  /// all contacting pins then (> 1: the outer pins slip first).
  double first_slip_radius_ratio = 0.0;
  /// Internal pin vs external marker displacement (sensor frame, since the retraction
  /// started, contacting pins, up to 0.3 s after the fall): Pearson correlation and the relative RMS
  /// difference |d_in - d_ext| / |d_ext|. NaN without an external camera.
  double tracking_correlation = 0.0;
  double tracking_error = 0.0;
  double detector_alarm_s = 0.0;    ///< first incipient-detector alarm after retraction starts
  double detector_lead_fall_s = 0.0;///< fall_s - detector_alarm_s (> 0: alarm before the fall)
  bool detected_before_fall = false;
  bool alarm_before_gross = false;  ///< the detector alarmed before ground-truth gross slip
  double peak_speed_px = 0.0;       ///< gross-slip signal: peak mean pin speed within 0.3 s of the onset, px/frame
  /// Where the slip starts: the compass sectors in the order of their first slipping pin
  /// over the incipient window (OrderIncipientSectors; physics steps where recorded).
  SectorOrder sectors;
};

/// Analyses one run (needs the full record) as sensor `sensor` of it recorded it. The
/// detector is reset at the start of the retraction and fed every frame from then on.
/// Throws std::invalid_argument if a per-pin array it reads does not hold a value per pin
/// and frame (SensorRecord::CheckPinArrays).
IncipientRunMetrics AnalyzeIncipientRun(const RunRecord& run, const SensorRecord& sensor,
                                        const IncipientParams& params);
/// AnalyzeIncipientRun of the run's first sensor.
IncipientRunMetrics AnalyzeIncipientRun(const RunRecord& run, const IncipientParams& params);

/// Summary over runs: means and spreads, counts.
struct IncipientSummary {
  int runs = 0;
  int with_incipient = 0;           ///< runs with a ground-truth incipient onset
  double lead_gross_mean_s = 0.0, lead_gross_std_s = 0.0;  ///< over runs with an onset (0 for runs without)
  double lead_fall_mean_s = 0.0;
  int lead_fall_over_half_s = 0;    ///< runs whose incipient onset precedes the fall by >= 0.5 s
  double pre_slip_fraction_mean = 0.0;
  double first_slip_radius_ratio_mean = 0.0;
  double tracking_correlation_mean = 0.0, tracking_error_mean = 0.0;
  int detected_before_fall = 0;     ///< detector alarms before the fall
  int alarm_before_gross = 0;       ///< detector alarms before gross slip
  double detector_lead_fall_mean_s = 0.0;  ///< over runs detected before the fall
  double peak_speed_mean_px = 0.0;
  /// Runs whose first slip is east/west only, with south before north, and with the
  /// hardware's whole order (east and west, then south, then north).
  int east_west_first = 0, south_before_north = 0, hardware_order = 0;
};

IncipientSummary SummarizeIncipient(const std::vector<IncipientRunMetrics>& runs);

/// Table of per-run metrics plus the summary, for the command line.
std::string FormatIncipientReport(const std::vector<IncipientRunMetrics>& runs, const IncipientSummary& s);

/// CSV of per-run metrics (header + one row per run).
std::string IncipientCsv(const std::vector<IncipientRunMetrics>& runs);

}  // namespace tactip
