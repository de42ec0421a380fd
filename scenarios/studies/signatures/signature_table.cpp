// The text of `tactip report signatures`: per-run tables of the gross-slip and the
// incipient-slip signatures, then one summary line per figure with the hardware's value
// (real-sensor.md sections 2 and 3) and issue 13's acceptance beside it.

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "scenarios/studies/signatures/signature_report.h"
#include "sim/base/nan.h"
#include "sim/base/number_text.h"

namespace tactip {

namespace {

constexpr const char* kNone = "none";

// A number, or "none" for an event that did not happen (NaN).
std::string SignatureCell(double v, const char* spec = "{:.2f}") { return NumberCell(v, spec, kNone); }

// "pass"/"fail" of one run against a threshold (a NaN figure fails).
std::string PassCell(bool pass) { return pass ? "pass" : "fail"; }

// "median [min, max] (k of n runs)" of the finite values; "none (0 of n runs)" without any.
std::string Spread(std::vector<double> values, const char* spec = "{:.2f}") {
  const size_t runs = values.size();
  std::erase_if(values, [](double v) { return !std::isfinite(v); });
  if (values.empty()) return fmt::format("none (0 of {} runs)", runs);
  std::sort(values.begin(), values.end());
  const size_t k = values.size();
  const double median = k % 2 ? values[k / 2] : 0.5 * (values[k / 2 - 1] + values[k / 2]);
  return fmt::format("{} [{}, {}] ({} of {} runs)", SignatureCell(median, spec), SignatureCell(values.front(), spec),
                     SignatureCell(values.back(), spec), k, runs);
}

// "passed/runs, needs N: PASS|FAIL" of one acceptance count.
std::string Verdict(const AcceptanceCount& c) {
  return fmt::format("{}/{}, needs {}: {}", c.passed, c.runs, c.min_passed, c.Pass() ? "PASS" : "FAIL");
}

// One summary line: figure, simulated spread, hardware value, acceptance.
std::string SummaryLine(const std::string& figure, const std::string& sim, const std::string& hardware,
                        const std::string& acceptance = "-") {
  return fmt::format("  {:<31} {:<38} {:<37} {}\n", figure, sim, hardware, acceptance);
}

// The gross-slip figures of the runs that have them, one vector per figure.
struct GrossColumns {
  std::vector<double> noise, noise_w5, width, peak, peak_w5, colinear_onset, colinear_later, contact_lost,
      step, after_w5;
};

// One row of the gross-slip table; fills the columns.
std::string GrossRow(const SignatureRun& r, GrossColumns& c) {
  if (!r.gross) return fmt::format("{:>4} {:>6} {:>6}\n", r.run, SignatureCell(r.speed_mm_s), kNotApplicable);
  const GrossSignature& g = *r.gross;
  const double width = g.spike_width_frames < 0 ? kNaN : g.spike_width_frames;
  c.noise.push_back(g.noise.mean_speed_px);
  c.noise_w5.push_back(g.noise.mean_speed_w5_px);
  c.width.push_back(width);
  c.peak.push_back(g.spike_peak_px);
  c.peak_w5.push_back(g.spike_peak_w5_px);
  c.colinear_onset.push_back(g.colinear_onset);
  c.colinear_later.push_back(g.colinear_later);
  c.contact_lost.push_back(g.contact_lost_s);
  c.step.push_back(g.step_px);
  c.after_w5.push_back(g.after_w5_px);
  return fmt::format("{:>4} {:>6} {:>6} {:>8} {:>6} {:>6} {:>5} {:>6} {:>7} {:>7} {:>7} {:>7} {:>6} {:>8}\n", r.run,
                     SignatureCell(r.speed_mm_s), SignatureCell(g.noise.mean_speed_px), SignatureCell(g.noise.mean_speed_w5_px),
                     SignatureCell(g.noise.Level()), std::isnan(width) ? kNotApplicable : std::to_string(g.spike_width_frames),
                     PassCell(g.spike_width_frames >= kAcceptedSpikeFrames), SignatureCell(g.spike_peak_px),
                     SignatureCell(g.spike_peak_w5_px), SignatureCell(g.colinear_onset), SignatureCell(g.colinear_later),
                     SignatureCell(g.contact_lost_s, "{:.3f}"), SignatureCell(g.step_px), SignatureCell(g.after_w5_px));
}

// The gross-slip per-run table and summary.
std::string GrossSection(const std::vector<SignatureRun>& runs, const AcceptanceCount& width, double held_window_s) {
  if (width.runs == 0) return "gross slip: n/a (no run has a gross-slip onset)\n";
  std::string out = fmt::format(
      "gross slip: {} of {} runs have an onset; noise over the {} s before the retraction, level = mean + {} std\n",
      width.runs, runs.size(), held_window_s, kNoiseSigmas);
  out += fmt::format("{:>4} {:>6} {:>6} {:>8} {:>6} {:>6} {:>5} {:>6} {:>7} {:>7} {:>7} {:>7} {:>6} {:>8}\n", "run",
                     "speed", "noise", "noise_w5", "level", "width", ">=15", "peak", "peak_w5", "colin_0", "colin_5",
                     "lost_s", "step", "after_w5");
  GrossColumns c;
  for (const SignatureRun& r : runs) out += GrossRow(r, c);
  // Summary: each figure's spread beside the hardware's value and the acceptance.
  out += SummaryLine("figure", "simulated: median [min, max]", "hardware", "acceptance");
  out += SummaryLine("static noise, px/frame", Spread(c.noise), "~0.5");
  out += SummaryLine("static noise W5, px/frame", Spread(c.noise_w5), "~0.1");
  out += SummaryLine("spike width, frames", Spread(c.width, "{:.0f}"), "~20 (~0.2 s, onset to contact lost)",
                     ">= 15 in >= 80 % of runs: " + Verdict(width));
  out += SummaryLine("spike peak, px/frame", Spread(c.peak), "almost all pins move fast");
  out += SummaryLine("spike peak W5, px/frame", Spread(c.peak_w5), "-");
  out += SummaryLine("co-linear share at onset", Spread(c.colinear_onset), "co-linear, upwards");
  out += SummaryLine(fmt::format("co-linear share {} frames later", kColinearLaterFrames), Spread(c.colinear_later),
                     "messy (elastic effects, contact loss)");
  out += SummaryLine("onset -> contact lost, s", Spread(c.contact_lost, "{:.3f}"), "~0.2");
  out += SummaryLine("pattern step at gross slip, px", Spread(c.step), "a step change");
  out += SummaryLine(fmt::format("W5 {}-{} frames after, px/frame", kStepAfterFirstFrame, kStepAfterEndFrame),
                     Spread(c.after_w5), "then flat (noise W5 ~0.1)");
  return out;
}

// The incipient-slip figures of the runs that have them, one vector per figure.
struct IncipientColumns {
  std::vector<double> visible_lead, excess, pin_excess, amplitude_w1, amplitude_w5, alarm_lead, correlation;
  AlarmPins alarm_pins;  // summed over the runs that alarmed
  int alarmed_runs = 0;
};

// The labels of the alarm's pins as "slipping/stuck/free", or "none" without an alarm.
std::string AlarmPinsCell(const IncipientSignature& s) {
  if (std::isnan(s.alarm_s)) return kNone;
  return fmt::format("{}/{}/{}", s.alarm_pins.slipping, s.alarm_pins.stuck, s.alarm_pins.free);
}

// The summed labels of the alarms' pins over the runs that alarmed.
std::string AlarmPinsSummary(const IncipientColumns& c) {
  if (c.alarmed_runs == 0) return "no alarm";
  const int total = c.alarm_pins.total();
  return fmt::format("{}/{}/{} of {} in {} runs ({:.0f} % slip)", c.alarm_pins.slipping, c.alarm_pins.stuck,
                     c.alarm_pins.free, total, c.alarmed_runs, 100.0 * c.alarm_pins.slipping / total);
}

// One row of the incipient table; fills the columns. Without an incipient phase the
// amplitudes and sectors do not apply; without external markers the correlation.
std::string IncipientRow(const SignatureRun& r, IncipientColumns& c) {
  if (!r.incipient) return fmt::format("{:>4} {:>6} {:>9}\n", r.run, SignatureCell(r.speed_mm_s), kNotApplicable);
  const IncipientSignature& s = *r.incipient;
  auto phase = [&](double v) { return s.has_phase ? SignatureCell(v) : std::string(kNotApplicable); };
  c.visible_lead.push_back(s.visible_lead_s);
  if (!std::isnan(s.sustained_excess_px)) c.excess.push_back(s.sustained_excess_px);
  if (!std::isnan(s.pin_sustained_excess_px)) c.pin_excess.push_back(s.pin_sustained_excess_px);
  c.alarm_lead.push_back(s.alarm_lead_s);
  if (s.has_phase) c.amplitude_w1.push_back(s.amplitude_w1_px);
  if (s.has_phase) c.amplitude_w5.push_back(s.amplitude_w5_px);
  if (s.has_external) c.correlation.push_back(s.tracking_correlation);
  if (!std::isnan(s.alarm_s)) {
    c.alarm_pins += s.alarm_pins;
    ++c.alarmed_runs;
  }
  const std::string first = s.sectors.first.empty() ? kNone : s.sectors.first;
  const std::string order = s.sectors.order.empty() ? kNone : s.sectors.order;
  return fmt::format("{:>4} {:>6} {:>9} {:>8} {:>5} {:>6} {:>6} {:>6} {:>6} {:>9} {:>8} {:>5} {:>8} {:>7} {:>7} {:>9} {:>6}\n",
                     r.run, SignatureCell(r.speed_mm_s), SignatureCell(s.visible_s, "{:.3f}"), SignatureCell(s.visible_lead_s, "{:.3f}"),
                     PassCell(s.visible_lead_s >= kAcceptedLeadS), SignatureCell(s.sustained_excess_px),
                     SignatureCell(s.pin_sustained_excess_px),
                     phase(s.amplitude_w1_px),
                     phase(s.amplitude_w5_px), SignatureCell(s.alarm_s, "{:.3f}"), SignatureCell(s.alarm_lead_s, "{:.3f}"),
                     PassCell(s.alarm_lead_s >= kAcceptedLeadS), AlarmPinsCell(s),
                     s.alarm_sector.empty() ? kNone : s.alarm_sector, s.has_phase ? first : kNotApplicable,
                     s.has_phase ? order : kNotApplicable,
                     s.has_external ? SignatureCell(s.tracking_correlation, "{:.3f}") : kNotApplicable);
}

// How the runs' sectors were ordered: "by physics step", "by frame" or "by physics step in k of n".
std::string SectorResolution(const SignatureAcceptance& a) {
  if (a.sectors_at_steps == a.east_west_first.runs) return "by physics step";
  if (a.sectors_at_steps == 0) return "by frame";
  return fmt::format("by physics step in {} of {}", a.sectors_at_steps, a.east_west_first.runs);
}

// The incipient per-run table and summary.
std::string IncipientSection(const std::vector<SignatureRun>& runs, const SignatureAcceptance& a,
                             const IncipientParams& params) {
  const auto onsets = std::count_if(runs.begin(), runs.end(), [](const SignatureRun& r) { return r.incipient_onset; });
  if (a.visible_lead.runs == 0) {
    return fmt::format("incipient slip: n/a (no fingerprint-skin run with a fall; hardware: a smooth skin shows no "
                       "incipient slip); ground-truth incipient onset in {} of {} runs\n",
                       onsets, runs.size());
  }
  std::string out = fmt::format(
      "incipient slip: {} of {} runs apply (fingerprint skin, fall or incipient onset); incipient onset in {}; "
      "detector W {}, s_thr {} px, I_thr {}\n",
      a.visible_lead.runs, runs.size(), onsets, params.window, params.speed_thr_px, params.count_thr);
  out += fmt::format("{:>4} {:>6} {:>9} {:>8} {:>5} {:>6} {:>6} {:>6} {:>6} {:>9} {:>8} {:>5} {:>8} {:>7} {:>7} {:>9} {:>6}\n",
                     "run", "speed", "visible_s", "vis_lead", ">=0.5", "excess", "pin_ex", "amp_w1", "amp_w5", "alarm_s",
                     "alarm_ld", ">=0.5", "pins_skf", "a_sec", "first", "order", "corr");
  IncipientColumns c;
  for (const SignatureRun& r : runs) out += IncipientRow(r, c);
  // Summary: each figure's spread beside the hardware's value and the acceptance.
  out += SummaryLine("figure", "simulated: median [min, max]", "hardware", "acceptance");
  out += SummaryLine("visible before the fall, s", Spread(c.visible_lead, "{:.3f}"), ">= 0.5, often seconds",
                     ">= 0.5 s in >= 90 % of runs: " + Verdict(a.visible_lead));
  out += SummaryLine("sustained excess, px/frame", Spread(c.excess),
                     fmt::format("> {} (s_thr) for {} frames", params.speed_thr_px, params.window));
  out += SummaryLine("sustained excess, best pin", Spread(c.pin_excess),
                     fmt::format("> {} (s_thr) for {} frames", params.speed_thr_px, params.window));
  out += SummaryLine("amplitude W1, px/frame", Spread(c.amplitude_w1), "~1.0 (noise ~0.5)");
  out += SummaryLine("amplitude W5, px/frame", Spread(c.amplitude_w5), "~0.4 (noise ~0.1)");
  out += SummaryLine("detector alarm before fall, s", Spread(c.alarm_lead, "{:.3f}"), "stopped in time in 17 of 20",
                     ">= 0.5 s in >= 17/20 of runs: " + Verdict(a.alarm_lead));
  out += SummaryLine("alarm pins slip/stuck/free", AlarmPinsSummary(c), "not labelled");
  out += SummaryLine("first-slipping sector",
                     fmt::format("E/W first {} of {}, tied with S/N {} ({})", a.east_west_first.passed,
                                 a.east_west_first.runs, a.east_west_tied, SectorResolution(a)),
                     "E and W first, then S, then N", "E/W in most runs: " + Verdict(a.east_west_first));
  out += SummaryLine("first-moving sector (camera)",
                     fmt::format("E/W {} of {} alarms (detector's first alarm set)", a.east_west_alarm, a.alarmed),
                     "E and W first (as observed)");
  out += SummaryLine("sector order",
                     fmt::format("S before N {} of {}; E and W, then S, then N {} of {}", a.south_before_north,
                                 a.east_west_first.runs, a.hardware_order, a.east_west_first.runs),
                     "S before N; that whole order");
  out += SummaryLine("internal/external correlation",
                     c.correlation.empty() ? std::string("n/a (no external markers)") : Spread(c.correlation),
                     "v2 alike (~1), v1 differ");
  return out;
}

}  // namespace

std::string FormatSignatureReport(const std::vector<SignatureRun>& runs, const SignatureOptions& options) {
  const SignatureAcceptance a = JudgeSignatures(runs);
  return GrossSection(runs, a.spike_width, options.held_window_s) + "\n" + IncipientSection(runs, a, options.detector);
}

}  // namespace tactip
