#include "scenarios/studies/incipient_report/incipient_report.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "scenarios/studies/run_signals/incipient_signals.h"
#include "scenarios/studies/run_signals/run_signals.h"
#include "sim/base/nan.h"

namespace tactip {

namespace {

constexpr double kPeakWindowS = 0.3;  // gross-slip signal: peak within this long after the onset

// Mean and sample standard deviation of the finite values.
std::pair<double, double> MeanStd(const std::vector<double>& v) {
  double s = 0.0, s2 = 0.0;
  int n = 0;
  for (double x : v) {
    if (!std::isfinite(x)) continue;
    s += x;
    s2 += x * x;
    ++n;
  }
  if (n == 0) return {kNaN, kNaN};
  const double m = s / n;
  const double var = n > 1 ? std::max(0.0, (s2 - n * m * m) / (n - 1)) : 0.0;
  return {m, std::sqrt(var)};
}

}  // namespace

IncipientRunMetrics AnalyzeIncipientRun(const RunRecord& r, const SensorRecord& sensor, const IncipientParams& params) {
  sensor.CheckPinArrays(r.frames(), fmt::format("incipient analysis of run {}, sensor '{}': ", r.index, sensor.name));
  IncipientRunMetrics m;
  m.run = r.index;
  m.retract_start_s = RunAttr(r, "retract_start_s");
  m.incipient_onset_s = RunAttr(r, "incipient_onset_s");
  m.gross_onset_s = RunAttr(r, "gross_slip_onset_s");
  m.fall_s = RunAttr(r, "object_fall_s");
  m.lead_gross_s = m.gross_onset_s - m.incipient_onset_s;
  m.lead_fall_s = m.fall_s - m.incipient_onset_s;
  m.pre_slip_fraction = RunAttr(r, "pre_slip_fraction");
  const size_t T = r.frames(), N = static_cast<size_t>(sensor.n_pins);
  const IncipientWindow window = IncipientWindowOf(r);
  const size_t f0 = window.from_frame;
  auto radius = [&](size_t i) {  // distance of pin i's marker from the sensor axis, at frame 0
    return std::hypot(sensor.pos_m[i * 3 + 1], sensor.pos_m[i * 3 + 2]);
  };

  // Which pins slip first: at the incipient onset frame.
  m.first_slip_radius_ratio = kNaN;
  if (!std::isnan(m.incipient_onset_s)) {
    const size_t f = FrameAt(r, m.incipient_onset_s);
    double rs = 0.0, rc = 0.0;
    int ns = 0, nc = 0;
    for (size_t i = 0; f < T && i < N; ++i) {
      if (!sensor.pin_contact[f * N + i]) continue;
      rc += radius(i);
      ++nc;
      if (sensor.pin_slip[f * N + i]) {
        rs += radius(i);
        ++ns;
      }
    }
    if (ns > 0 && nc > 0 && rc > 0.0) m.first_slip_radius_ratio = (rs / ns) / (rc / nc);
  }

  // Internal vs external tracking, in the sensor frame (no mirroring), displacements
  // since the retraction started, of the pins in contact then.
  const MarkerTracking tracking = TrackMarkers(r, sensor);
  m.tracking_correlation = tracking.correlation;
  m.tracking_error = tracking.error;

  // The incipient detector from the retraction on.
  m.detector_alarm_s = FirstIncipientAlarm(r, sensor, params, f0).time_s;
  m.detector_lead_fall_s = m.fall_s - m.detector_alarm_s;
  m.detected_before_fall = !std::isnan(m.detector_alarm_s) && (std::isnan(m.fall_s) || m.detector_alarm_s < m.fall_s);
  m.alarm_before_gross =
      !std::isnan(m.detector_alarm_s) && (std::isnan(m.gross_onset_s) || m.detector_alarm_s < m.gross_onset_s);

  // Gross-slip signal strength: peak mean pin speed (px/frame) just after the onset.
  m.peak_speed_px = std::isnan(m.gross_onset_s) ? kNaN : PeakMeanPinSpeedPx(r, sensor, m.gross_onset_s, kPeakWindowS);
  m.sectors = OrderIncipientSectors(sensor, window, false);
  return m;
}

IncipientRunMetrics AnalyzeIncipientRun(const RunRecord& r, const IncipientParams& params) {
  return AnalyzeIncipientRun(r, r.sensors.front(), params);
}

IncipientSummary SummarizeIncipient(const std::vector<IncipientRunMetrics>& runs) {
  IncipientSummary s;
  s.runs = static_cast<int>(runs.size());
  std::vector<double> lead_g, lead_f, pre, ratio, corr, err, det_lead, peak;
  for (const auto& m : runs) {
    // A run without an incipient onset has no incipient window: lead 0.
    lead_g.push_back(std::isnan(m.incipient_onset_s) ? 0.0 : m.lead_gross_s);
    if (!std::isnan(m.incipient_onset_s)) {
      ++s.with_incipient;
      lead_f.push_back(m.lead_fall_s);
      if (m.lead_fall_s >= 0.5) ++s.lead_fall_over_half_s;
    }
    pre.push_back(m.pre_slip_fraction);
    ratio.push_back(m.first_slip_radius_ratio);
    corr.push_back(m.tracking_correlation);
    err.push_back(m.tracking_error);
    if (m.detected_before_fall) {
      ++s.detected_before_fall;
      det_lead.push_back(m.detector_lead_fall_s);
    }
    if (m.alarm_before_gross) ++s.alarm_before_gross;
    peak.push_back(m.peak_speed_px);
    s.east_west_first += m.sectors.EastWestFirst() ? 1 : 0;
    s.south_before_north += m.sectors.SouthBeforeNorth() ? 1 : 0;
    s.hardware_order += m.sectors.HardwareOrder() ? 1 : 0;
  }
  std::tie(s.lead_gross_mean_s, s.lead_gross_std_s) = MeanStd(lead_g);
  s.lead_fall_mean_s = MeanStd(lead_f).first;
  s.pre_slip_fraction_mean = MeanStd(pre).first;
  s.first_slip_radius_ratio_mean = MeanStd(ratio).first;
  s.tracking_correlation_mean = MeanStd(corr).first;
  s.tracking_error_mean = MeanStd(err).first;
  s.detector_lead_fall_mean_s = MeanStd(det_lead).first;
  s.peak_speed_mean_px = MeanStd(peak).first;
  return s;
}

namespace {
std::string F(double v, const char* spec = "{:.3f}") { return std::isnan(v) ? "-" : fmt::format(fmt::runtime(spec), v); }
}  // namespace

std::string FormatIncipientReport(const std::vector<IncipientRunMetrics>& runs, const IncipientSummary& s) {
  std::string out =
      fmt::format("{:>4} {:>9} {:>9} {:>9} {:>8} {:>8} {:>6} {:>7} {:>6} {:>7} {:>9} {:>8} {:>7} {:>9}\n", "run",
                  "incip_s", "gross_s", "fall_s", "lead_gs", "lead_fs", "pre", "r_first", "corr", "trk_err", "alarm_s",
                  "alarm_ld", "peak", "sectors");
  for (const auto& m : runs) {
    out += fmt::format("{:>4} {:>9} {:>9} {:>9} {:>8} {:>8} {:>6} {:>7} {:>6} {:>7} {:>9} {:>8} {:>7} {:>9}\n", m.run,
                       F(m.incipient_onset_s), F(m.gross_onset_s), F(m.fall_s), F(m.lead_gross_s), F(m.lead_fall_s),
                       F(m.pre_slip_fraction, "{:.2f}"), F(m.first_slip_radius_ratio, "{:.2f}"),
                       F(m.tracking_correlation, "{:.3f}"), F(m.tracking_error, "{:.3f}"), F(m.detector_alarm_s),
                       F(m.detector_lead_fall_s), F(m.peak_speed_px, "{:.2f}"),
                       m.sectors.order.empty() ? "-" : m.sectors.order);
  }
  out += fmt::format(
      "summary: {} runs; incipient onset in {}; lead before gross slip {} +- {} s (runs without an onset count 0); "
      "lead before the fall {} s, >= 0.5 s in {} runs; pins slipping before gross slip {}; first-slip radius "
      "ratio {}; internal/external tracking correlation {}, error {}; detector alarm before the fall in {}/{} runs "
      "(mean lead {} s), before gross slip in {}/{}; peak mean pin speed {} px/frame; first slip east/west in {}/{} "
      "runs, south before north in {}/{}, east and west then south then north in {}/{}\n",
      s.runs, s.with_incipient, F(s.lead_gross_mean_s), F(s.lead_gross_std_s), F(s.lead_fall_mean_s),
      s.lead_fall_over_half_s, F(s.pre_slip_fraction_mean, "{:.2f}"), F(s.first_slip_radius_ratio_mean, "{:.2f}"),
      F(s.tracking_correlation_mean), F(s.tracking_error_mean), s.detected_before_fall, s.runs,
      F(s.detector_lead_fall_mean_s), s.alarm_before_gross, s.runs, F(s.peak_speed_mean_px, "{:.2f}"),
      s.east_west_first, s.runs, s.south_before_north, s.runs, s.hardware_order, s.runs);
  return out;
}

std::string IncipientCsv(const std::vector<IncipientRunMetrics>& runs) {
  std::string out =
      "run,retract_start_s,incipient_onset_s,gross_onset_s,fall_s,lead_gross_s,lead_fall_s,pre_slip_fraction,"
      "first_slip_radius_ratio,tracking_correlation,tracking_error,detector_alarm_s,detector_lead_fall_s,"
      "detected_before_fall,alarm_before_gross,peak_speed_px,sector_order,east_west_first,south_before_north,"
      "hardware_order\n";
  auto g = [](double v) { return std::isnan(v) ? std::string("nan") : fmt::format("{:.6g}", v); };
  for (const auto& m : runs) {
    out += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", m.run, g(m.retract_start_s),
                       g(m.incipient_onset_s), g(m.gross_onset_s), g(m.fall_s), g(m.lead_gross_s), g(m.lead_fall_s),
                       g(m.pre_slip_fraction), g(m.first_slip_radius_ratio), g(m.tracking_correlation),
                       g(m.tracking_error), g(m.detector_alarm_s), g(m.detector_lead_fall_s),
                       m.detected_before_fall ? 1 : 0, m.alarm_before_gross ? 1 : 0, g(m.peak_speed_px),
                       m.sectors.order.empty() ? "none" : m.sectors.order, m.sectors.EastWestFirst() ? 1 : 0,
                       m.sectors.SouthBeforeNorth() ? 1 : 0, m.sectors.HardwareOrder() ? 1 : 0);
  }
  return out;
}

}  // namespace tactip
