#include "scenarios/studies/signatures/incipient_signature.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "scenarios/studies/run_signals/incipient_signals.h"
#include "scenarios/studies/run_signals/run_signals.h"
#include "scenarios/studies/signatures/held_noise.h"
#include "sim/base/nan.h"

namespace tactip {

namespace {


// Whether pin i is labelled slipping (in contact and sliding) at frame f.
bool LabelledSlipping(const SensorRecord& sensor, size_t f, size_t i) {
  const size_t k = f * static_cast<size_t>(sensor.n_pins) + i;
  return sensor.pin_contact[k] && sensor.pin_slip[k];
}

// Mean smoothed speed (window w) of the labelled-slipping pins at frame f and, when
// `bulk` is given, of the others; NaN where a group has no pin with a velocity. When
// `speeds` is given it receives each pin's smoothed speed (NaN without a velocity).
double SlippingSpeedPx(const SensorRecord& sensor, size_t f, int w, double* bulk = nullptr,
                       std::vector<double>* speeds = nullptr) {
  const auto n = static_cast<size_t>(sensor.n_pins);
  if (speeds) speeds->assign(n, kNaN);
  double slip_sum = 0.0, rest_sum = 0.0;
  int slip_count = 0, rest_count = 0;
  for (size_t i = 0; i < n; ++i) {
    const auto v = SmoothedPinVelocityPx(sensor, f, i, w);
    if (!v) continue;
    const double speed = std::hypot((*v)[0], (*v)[1]);
    if (speeds) (*speeds)[i] = speed;
    if (LabelledSlipping(sensor, f, i)) {
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

// The slipping pins' smoothed speed (window params.window) minus the bulk's, per frame f in
// [first, end) (element f - first): `mean` over the labelled-slipping pins (NaN where none
// is), `per_pin[i]` for pin i alone (NaN on the frames it is not labelled slipping or has
// no velocity). A bulk without a pin with a velocity counts 0.
struct ExcessSpeeds {
  std::vector<double> mean;
  std::vector<std::vector<double>> per_pin;
};

ExcessSpeeds ExcessSpeedsPx(const SensorRecord& sensor, size_t first, size_t end, const IncipientParams& params) {
  const auto n = static_cast<size_t>(sensor.n_pins);
  ExcessSpeeds excess;
  excess.per_pin.resize(n);
  std::vector<double> speeds;
  for (size_t f = first; f < end; ++f) {
    double bulk = kNaN;
    const double slipping = SlippingSpeedPx(sensor, f, params.window, &bulk, &speeds);
    if (std::isnan(bulk)) bulk = 0.0;
    excess.mean.push_back(slipping - bulk);
    for (size_t i = 0; i < n; ++i) {
      excess.per_pin[i].push_back(LabelledSlipping(sensor, f, i) ? speeds[i] - bulk : kNaN);
    }
  }
  return excess;
}

// First frame time starting params.window consecutive frames whose excess passes
// params.speed_thr_px (excess[k] is frame first + k); NaN if none.
double FirstVisibleS(const RunRecord& run, const std::vector<double>& excess, size_t first,
                     const IncipientParams& params) {
  int streak = 0;
  for (size_t k = 0; k < excess.size(); ++k) {
    streak = excess[k] > params.speed_thr_px ? streak + 1 : 0;  // NaN compares false
    if (streak == params.window) return run.time[first + k + 1 - static_cast<size_t>(params.window)];
  }
  return kNaN;
}

// The largest excess held for params.window consecutive frames: the largest, over every
// window of that many frames with slipping pins throughout, of the window's smallest
// excess. The run is visible exactly when this passes params.speed_thr_px. NaN if no
// such window.
double SustainedExcessPx(const std::vector<double>& excess, const IncipientParams& params) {
  const auto w = static_cast<size_t>(params.window);
  double best = kNaN;
  for (size_t k = 0; k + w <= excess.size(); ++k) {
    const auto begin = excess.begin() + static_cast<std::ptrdiff_t>(k);
    if (std::any_of(begin, begin + static_cast<std::ptrdiff_t>(w), [](double e) { return std::isnan(e); })) continue;
    const double low = *std::min_element(begin, begin + static_cast<std::ptrdiff_t>(w));
    best = std::isnan(best) ? low : std::max(best, low);
  }
  return best;
}

// The best single pin's sustained excess: the largest SustainedExcessPx over the pins'
// own excess series (ExcessSpeeds::per_pin); NaN if no pin slips params.window
// consecutive frames.
double PinSustainedExcessPx(const ExcessSpeeds& excess, const IncipientParams& params) {
  double best = kNaN;
  for (const std::vector<double>& series : excess.per_pin) {
    const double e = SustainedExcessPx(series, params);
    if (!std::isnan(e)) best = std::isnan(best) ? e : std::max(best, e);
  }
  return best;
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

// The labels, at the alarm's frame, of the pins in the detector's slipping set (none
// without an alarm: the set is empty).
AlarmPins LabelAlarmPins(const SensorRecord& sensor, const IncipientAlarm& alarm) {
  AlarmPins pins;
  const auto n = static_cast<size_t>(sensor.n_pins);
  for (int i : alarm.pins) {
    const size_t k = alarm.frame * n + static_cast<size_t>(i);
    if (!sensor.pin_contact[k]) {
      ++pins.free;
    } else if (sensor.pin_slip[k]) {
      ++pins.slipping;
    } else {
      ++pins.stuck;
    }
  }
  return pins;
}

}  // namespace

std::optional<IncipientSignature> MeasureIncipientSignature(const RunRecord& run, const SensorRecord& sensor,
                                                            const IncipientParams& params, bool sectors_by_frame) {
  // Applies to fingerprint skins with an incipient onset or a fall.
  const auto pattern = sensor.text_attrs.find("skin_pattern");
  const bool fingerprint = pattern != sensor.text_attrs.end() && pattern->second.rfind("fingerprint", 0) == 0;
  const double onset_s = RunAttr(run, "incipient_onset_s"), fall_s = RunAttr(run, "object_fall_s");
  if (!fingerprint || (std::isnan(onset_s) && std::isnan(fall_s))) return std::nullopt;
  const IncipientDetector check(params);  // throws InputError for bad parameters
  // The incipient window: retraction start to gross-slip onset (or fall, or the end).
  const IncipientWindow window = IncipientWindowOf(run);
  const size_t retract = window.from_frame, end = window.end_frame;
  const size_t first = std::max<size_t>(1, retract);  // the first frame with a velocity

  IncipientSignature s;
  s.has_phase = !std::isnan(onset_s);
  s.has_external = !sensor.external_m.empty();
  // Camera visibility and the detector, both measured against the fall.
  const ExcessSpeeds excess = ExcessSpeedsPx(sensor, first, end, params);
  s.visible_s = FirstVisibleS(run, excess.mean, first, params);
  s.visible_lead_s = fall_s - s.visible_s;
  s.sustained_excess_px = SustainedExcessPx(excess.mean, params);
  s.pin_sustained_excess_px = PinSustainedExcessPx(excess, params);
  const IncipientAlarm alarm = FirstIncipientAlarm(run, sensor, params, retract);
  s.alarm_s = alarm.time_s;
  s.alarm_lead_s = fall_s - s.alarm_s;
  s.alarm_pins = LabelAlarmPins(sensor, alarm);
  s.alarm_sector = MostCommonSector(sensor, retract, alarm.pins);
  // Amplitudes of the slipping pins, where they slip, and the marker agreement.
  s.amplitude_w1_px = s.has_phase ? PeakSlippingSpeedPx(sensor, first, end, 1) : kNaN;
  s.amplitude_w5_px = s.has_phase ? PeakSlippingSpeedPx(sensor, first, end, kSmoothingFrames) : kNaN;
  s.sectors = OrderIncipientSectors(sensor, window, sectors_by_frame);
  s.tracking_correlation = TrackMarkers(run, sensor).correlation;
  return s;
}

}  // namespace tactip
