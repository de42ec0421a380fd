// The CSV of `tactip report signatures`: one row per run, "n/a" where a figure does not
// apply and "none" where its event did not happen (as in the printed table).

#include <cmath>

#include <fmt/format.h>

#include "scenarios/studies/signatures/signature_report.h"

namespace tactip {

namespace {

// A number with 6 significant digits, or "none" (NaN: did not happen).
std::string Value(double v) { return std::isnan(v) ? std::string("none") : fmt::format("{:.6g}", v); }

// The gross-slip columns of a run ("n/a" each without an onset).
std::string GrossCells(const SignatureRun& r) {
  if (!r.gross) return fmt::format("{0},{0},{0},{0},{0},{0},{0},{0},{0},{0}", kNotApplicable);
  const GrossSignature& g = *r.gross;
  const bool width_known = g.spike_width_frames >= 0;
  return fmt::format("{},{},{},{},{},{},{},{},{},{}", Value(g.noise.mean_speed_px), Value(g.noise.mean_speed_w5_px),
                     Value(g.noise.Level()), width_known ? std::to_string(g.spike_width_frames) : kNotApplicable,
                     g.spike_width_frames >= kAcceptedSpikeFrames ? 1 : 0, Value(g.spike_peak_px),
                     Value(g.spike_peak_w5_px), Value(g.colinear_onset), Value(g.colinear_later),
                     Value(g.contact_lost_s));
}

// The incipient columns of a run ("n/a" each where they do not apply).
std::string IncipientCells(const SignatureRun& r) {
  if (!r.incipient) return fmt::format("{0},{0},{0},{0},{0},{0},{0},{0},{0},{0},{0},{0},{0},{0},{0}", kNotApplicable);
  const IncipientSignature& s = *r.incipient;
  auto phase = [&](const std::string& v) { return s.has_phase ? v : std::string(kNotApplicable); };
  const bool alarmed = !std::isnan(s.alarm_s);
  auto pins = [&](int count) { return alarmed ? std::to_string(count) : std::string("none"); };
  return fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}", Value(s.visible_s), Value(s.visible_lead_s),
                     s.visible_lead_s >= kAcceptedLeadS ? 1 : 0, phase(Value(s.amplitude_w1_px)),
                     phase(Value(s.amplitude_w5_px)), Value(s.alarm_s), Value(s.alarm_lead_s),
                     s.alarm_lead_s >= kAcceptedLeadS ? 1 : 0,
                     phase(s.sectors.first.empty() ? "none" : s.sectors.first),
                     phase(s.sectors.order.empty() ? "none" : s.sectors.order),
                     s.has_external ? Value(s.tracking_correlation) : kNotApplicable,
                     Value(s.sustained_excess_px), pins(s.alarm_pins.slipping), pins(s.alarm_pins.stuck),
                     pins(s.alarm_pins.free));
}

// The gross-slip columns added after the incipient ones ("n/a" each without an onset).
std::string GrossStepCells(const SignatureRun& r) {
  if (!r.gross) return fmt::format("{0},{0}", kNotApplicable);
  return fmt::format("{},{}", Value(r.gross->step_px), Value(r.gross->after_w5_px));
}

// The camera's first-moving sector and the best pin's sustained excess, added last ("n/a"
// each without an incipient signature; "none" without an alarm, or without a pin slipping
// for the detector's window).
std::string LateIncipientCells(const SignatureRun& r) {
  if (!r.incipient) return fmt::format("{0},{0}", kNotApplicable);
  const IncipientSignature& s = *r.incipient;
  return fmt::format("{},{}", s.alarm_sector.empty() ? "none" : s.alarm_sector, Value(s.pin_sustained_excess_px));
}

}  // namespace

std::string SignatureCsv(const std::vector<SignatureRun>& runs) {
  std::string out =
      "run,speed_mm_s,skin,incipient_onset,noise_px,noise_w5_px,noise_level_px,spike_width_frames,spike_width_pass,"
      "spike_peak_px,spike_peak_w5_px,colinear_onset,colinear_later,contact_lost_s,visible_s,visible_lead_s,"
      "visible_pass,amplitude_w1_px,amplitude_w5_px,alarm_s,alarm_lead_s,alarm_pass,first_sector,sector_order,"
      "tracking_correlation,sustained_excess_px,alarm_pins_slipping,alarm_pins_stuck,alarm_pins_free,step_px,after_w5_px,"
      "alarm_sector,pin_sustained_excess_px\n";
  for (const SignatureRun& r : runs) {
    out += fmt::format("{},{},{},{},{},{},{},{}\n", r.run, Value(r.speed_mm_s), r.skin.empty() ? kNotApplicable : r.skin,
                       r.incipient_onset ? 1 : 0, GrossCells(r), IncipientCells(r), GrossStepCells(r),
                       LateIncipientCells(r));
  }
  return out;
}

}  // namespace tactip
