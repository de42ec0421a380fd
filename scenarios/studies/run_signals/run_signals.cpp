#include "scenarios/studies/run_signals/run_signals.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tactip {

double RunAttr(const RunRecord& run, const char* key) {
  const auto it = run.attrs.find(key);
  return it == run.attrs.end() ? std::numeric_limits<double>::quiet_NaN() : it->second;
}

size_t FrameAt(const RunRecord& run, double t_s) {
  // A nanosecond of slack so an event stored at a frame's time lands on that frame.
  return static_cast<size_t>(std::lower_bound(run.time.begin(), run.time.end(), t_s - 1e-9) - run.time.begin());
}

IncipientWindow IncipientWindowOf(const RunRecord& run) {
  const double retract_s = RunAttr(run, "retract_start_s"), gross_s = RunAttr(run, "gross_slip_onset_s");
  const double end_s = std::isnan(gross_s) ? RunAttr(run, "object_fall_s") : gross_s;
  IncipientWindow w;
  w.from_s = std::isnan(retract_s) ? (run.time.empty() ? 0.0 : run.time.front()) : retract_s;
  w.end_s = std::isnan(end_s) ? std::numeric_limits<double>::infinity() : end_s;
  w.from_frame = std::isnan(retract_s) ? 0 : FrameAt(run, retract_s);
  w.end_frame = std::isnan(end_s) ? run.frames() : FrameAt(run, end_s);
  return w;
}

std::optional<std::array<double, 2>> PinVelocityPx(const SensorRecord& sensor, size_t f, size_t pin) {
  const auto n = static_cast<size_t>(sensor.n_pins);
  if (f == 0 || !sensor.valid[f * n + pin] || !sensor.valid[(f - 1) * n + pin]) return std::nullopt;
  const size_t now = (f * n + pin) * 2, before = ((f - 1) * n + pin) * 2;
  return std::array<double, 2>{static_cast<double>(sensor.pos_px[now]) - sensor.pos_px[before],
                               static_cast<double>(sensor.pos_px[now + 1]) - sensor.pos_px[before + 1]};
}

std::optional<std::array<double, 2>> SmoothedPinVelocityPx(const SensorRecord& sensor, size_t f, size_t pin,
                                                           int window) {
  // Sum the velocities of the last `window` frames that have one.
  double su = 0.0, sv = 0.0;
  int count = 0;
  for (int k = 0; k < window && static_cast<size_t>(k) <= f; ++k) {
    if (const auto v = PinVelocityPx(sensor, f - static_cast<size_t>(k), pin)) {
      su += (*v)[0];
      sv += (*v)[1];
      ++count;
    }
  }
  if (count == 0) return std::nullopt;
  return std::array<double, 2>{su / count, sv / count};
}

double MeanPinSpeedPx(const SensorRecord& sensor, size_t f, int window) {
  double sum = 0.0;
  int count = 0;
  for (size_t i = 0; i < static_cast<size_t>(sensor.n_pins); ++i) {
    if (const auto v = SmoothedPinVelocityPx(sensor, f, i, window)) {
      sum += std::hypot((*v)[0], (*v)[1]);
      ++count;
    }
  }
  return count > 0 ? sum / count : std::numeric_limits<double>::quiet_NaN();
}

double PeakMeanPinSpeedPx(const RunRecord& run, const SensorRecord& sensor, double from_s, double span_s,
                          int window) {
  const size_t first = std::max<size_t>(1, FrameAt(run, from_s));
  const size_t end = std::min(run.frames(), FrameAt(run, from_s + span_s) + 1);
  double peak = 0.0;
  for (size_t f = first; f < end; ++f) {
    const double s = MeanPinSpeedPx(sensor, f, window);
    if (std::isfinite(s)) peak = std::max(peak, s);
  }
  return peak;
}

}  // namespace tactip
