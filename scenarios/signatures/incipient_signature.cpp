#include "scenarios/signatures/incipient_signature.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "scenarios/incipient_signals.h"
#include "scenarios/run_signals.h"
#include "scenarios/signatures/held_noise.h"

namespace tactip {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Mean smoothed speed (window w) of the labelled-slipping pins at frame f and, when
// `bulk` is given, of the others; NaN where a group has no pin with a velocity.
double SlippingSpeedPx(const SensorRecord& sensor, size_t f, int w, double* bulk = nullptr) {
  const auto n = static_cast<size_t>(sensor.n_pins);
  double slip_sum = 0.0, rest_sum = 0.0;
  int slip_count = 0, rest_count = 0;
  for (size_t i = 0; i < n; ++i) {
    const auto v = SmoothedPinVelocityPx(sensor, f, i, w);
    if (!v) continue;
    const double speed = std::hypot((*v)[0], (*v)[1]);
    if (sensor.pin_contact[f * n + i] && sensor.pin_slip[f * n + i]) {
      slip_sum += speed;
      ++slip_count;
    } else {
      rest_sum += speed;
      ++rest_count;
    }
  }
  if (bulk) *bulk = rest_count > 0 ? rest_sum / rest_count : kNaN;
  return slip_count > 0 ? slip_sum / slip_count : kNaN;
}

// First frame time in [first, end) starting params.window consecutive frames on which the
// slipping pins' speed exceeds the bulk's by params.speed_thr_px; NaN if none.
double FirstVisibleS(const RunRecord& run, const SensorRecord& sensor, size_t first, size_t end,
                     const IncipientParams& params) {
  int streak = 0;
  for (size_t f = first; f < end; ++f) {
    double bulk = kNaN;
    const double slipping = SlippingSpeedPx(sensor, f, params.window, &bulk);
    const bool visible = slipping - (std::isnan(bulk) ? 0.0 : bulk) > params.speed_thr_px;
    streak = visible ? streak + 1 : 0;
    if (streak == params.window) return run.time[f + 1 - static_cast<size_t>(params.window)];
  }
  return kNaN;
}

// Peak over [first, end) of the slipping pins' mean speed with window w; NaN if none slipped.
double PeakSlippingSpeedPx(const SensorRecord& sensor, size_t first, size_t end, int w) {
  double peak = kNaN;
  for (size_t f = first; f < end; ++f) {
    const double s = SlippingSpeedPx(sensor, f, w);
    if (!std::isnan(s)) peak = std::isnan(peak) ? s : std::max(peak, s);
  }
  return peak;
}

}  // namespace

std::optional<IncipientSignature> MeasureIncipientSignature(const RunRecord& run, const SensorRecord& sensor,
                                                            const IncipientParams& params) {
  // Applies to fingerprint skins with an incipient onset or a fall.
  const auto pattern = sensor.text_attrs.find("skin_pattern");
  const bool fingerprint = pattern != sensor.text_attrs.end() && pattern->second.rfind("fingerprint", 0) == 0;
  const double onset_s = RunAttr(run, "incipient_onset_s"), fall_s = RunAttr(run, "object_fall_s");
  if (!fingerprint || (std::isnan(onset_s) && std::isnan(fall_s))) return std::nullopt;
  const IncipientDetector check(params);  // throws InputError for bad parameters
  // The incipient window: retraction start to gross-slip onset (or fall, or the end).
  const double retract_s = RunAttr(run, "retract_start_s"), gross_s = RunAttr(run, "gross_slip_onset_s");
  const double end_s = std::isnan(gross_s) ? fall_s : gross_s;
  const size_t retract = std::isnan(retract_s) ? 0 : FrameAt(run, retract_s);
  const size_t first = std::max<size_t>(1, retract);  // the first frame with a velocity
  const size_t end = std::isnan(end_s) ? run.frames() : FrameAt(run, end_s);

  IncipientSignature s;
  s.has_phase = !std::isnan(onset_s);
  s.has_external = !sensor.external_m.empty();
  // Camera visibility and the detector, both measured against the fall.
  s.visible_s = FirstVisibleS(run, sensor, first, end, params);
  s.visible_lead_s = fall_s - s.visible_s;
  s.alarm_s = FirstIncipientAlarmS(run, sensor, params, retract);
  s.alarm_lead_s = fall_s - s.alarm_s;
  // Amplitudes of the slipping pins, where they slip, and the marker agreement.
  s.amplitude_w1_px = s.has_phase ? PeakSlippingSpeedPx(sensor, first, end, 1) : kNaN;
  s.amplitude_w5_px = s.has_phase ? PeakSlippingSpeedPx(sensor, first, end, kSmoothingFrames) : kNaN;
  s.sectors = OrderSlipSectors(sensor, retract, end);
  s.tracking_correlation = TrackMarkers(run, sensor).correlation;
  return s;
}

}  // namespace tactip
