#include "scenarios/studies/signatures/signature_report.h"

#include <cmath>

#include "scenarios/studies/run_signals/run_signals.h"

namespace tactip {

namespace {

// The least whole number of runs that is at least `share` of `runs`.
int RunsNeeded(int runs, double share) { return static_cast<int>(std::ceil(share * runs - 1e-9)); }

}  // namespace

SignatureRun MeasureSignatures(const RunRecord& run, const SensorRecord& sensor, const SignatureOptions& options) {
  SignatureRun s;
  s.run = run.index;
  s.speed_mm_s = RunAttr(run, "retract_speed_mm_s");
  const auto skin = sensor.text_attrs.find("skin_pattern");
  s.skin = skin == sensor.text_attrs.end() ? "" : skin->second;
  s.incipient_onset = !std::isnan(RunAttr(run, "incipient_onset_s"));
  s.gross = MeasureGrossSignature(run, sensor, options.held_window_s);
  s.incipient = MeasureIncipientSignature(run, sensor, options.detector, options.sectors_by_frame);
  return s;
}

SignatureAcceptance JudgeSignatures(const std::vector<SignatureRun>& runs) {
  constexpr double kWidthShare = 0.8, kVisibleShare = 0.9, kAlarmShare = 17.0 / 20.0;
  SignatureAcceptance a;
  // Per-run thresholds; a figure that did not happen (NaN) fails.
  for (const SignatureRun& r : runs) {
    if (r.gross) {
      ++a.spike_width.runs;
      if (r.gross->spike_width_frames >= kAcceptedSpikeFrames) ++a.spike_width.passed;
    }
    if (r.incipient) {
      ++a.visible_lead.runs;
      ++a.alarm_lead.runs;
      ++a.east_west_first.runs;
      if (r.incipient->visible_lead_s >= kAcceptedLeadS) ++a.visible_lead.passed;
      if (r.incipient->alarm_lead_s >= kAcceptedLeadS) ++a.alarm_lead.passed;
      if (r.incipient->sectors.EastWestFirst()) ++a.east_west_first.passed;
      if (r.incipient->sectors.EastWestTiedWithNorthSouth()) ++a.east_west_tied;
      if (r.incipient->sectors.at_steps) ++a.sectors_at_steps;
      if (r.incipient->sectors.SouthBeforeNorth()) ++a.south_before_north;
      if (r.incipient->sectors.HardwareOrder()) ++a.hardware_order;
      if (!std::isnan(r.incipient->alarm_s)) ++a.alarmed;
      if (EastWestOnly(r.incipient->alarm_sector)) ++a.east_west_alarm;
    }
  }
  // Runs needed from the required shares ("most" = more than half).
  a.spike_width.min_passed = RunsNeeded(a.spike_width.runs, kWidthShare);
  a.visible_lead.min_passed = RunsNeeded(a.visible_lead.runs, kVisibleShare);
  a.alarm_lead.min_passed = RunsNeeded(a.alarm_lead.runs, kAlarmShare);
  a.east_west_first.min_passed = a.east_west_first.runs / 2 + 1;
  return a;
}

}  // namespace tactip
