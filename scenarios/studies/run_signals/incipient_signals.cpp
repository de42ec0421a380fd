#include "scenarios/studies/run_signals/incipient_signals.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "scenarios/studies/run_signals/run_signals.h"

namespace tactip {

IncipientAlarm FirstIncipientAlarm(const RunRecord& run, const SensorRecord& sensor, const IncipientParams& params,
                                   size_t from_frame) {
  IncipientDetector det(params);
  const auto n = static_cast<size_t>(sensor.n_pins);
  PinFrame frame;
  frame.pos_px.resize(static_cast<Eigen::Index>(n), 2);
  frame.valid.resize(n);
  // Feed every frame from `from_frame` on until the first alarm.
  for (size_t f = from_frame; f < run.frames(); ++f) {
    frame.time_s = run.time[f];
    for (size_t i = 0; i < n; ++i) {
      frame.pos_px(static_cast<Eigen::Index>(i), 0) = sensor.pos_px[(f * n + i) * 2];
      frame.pos_px(static_cast<Eigen::Index>(i), 1) = sensor.pos_px[(f * n + i) * 2 + 1];
      frame.valid[i] = sensor.valid[f * n + i];
    }
    Decision d = det.Update(frame);
    if (d.slip) return {run.time[f], f, std::move(d.slipping_pins)};
  }
  return {};
}

MarkerTracking TrackMarkers(const RunRecord& run, const SensorRecord& sensor) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  MarkerTracking m{kNaN, kNaN};
  // The window: the retraction up to kTrackingAfterFallS after the fall.
  const double retract_s = RunAttr(run, "retract_start_s"), fall_s = RunAttr(run, "object_fall_s");
  const size_t T = run.frames(), n = static_cast<size_t>(sensor.n_pins);
  const size_t f0 = std::isnan(retract_s) ? 0 : FrameAt(run, retract_s);
  const size_t end = std::isnan(fall_s) ? T : std::min(T, FrameAt(run, fall_s + kTrackingAfterFallS) + 1);
  if (sensor.external_m.empty() || f0 >= T) return m;
  // Sums over every (frame, contacting pin, axis) pair of external (x) and internal (y).
  double sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0, se = 0, sn = 0;
  long count = 0;
  for (size_t f = f0; f < end; ++f) {
    for (size_t i = 0; i < n; ++i) {
      if (!sensor.pin_contact[f0 * n + i]) continue;
      for (size_t k = 1; k <= 2; ++k) {
        const double din = sensor.pos_m[(f * n + i) * 3 + k] - sensor.pos_m[(f0 * n + i) * 3 + k];
        const double dex = sensor.external_m[(f * n + i) * 3 + k] - sensor.external_m[(f0 * n + i) * 3 + k];
        sx += dex;
        sy += din;
        sxx += dex * dex;
        syy += din * din;
        sxy += dex * din;
        se += (din - dex) * (din - dex);
        sn += dex * dex;
        ++count;
      }
    }
  }
  // Pearson correlation and relative RMS difference.
  if (count > 1) {
    const double cov = sxy - sx * sy / count, vx = sxx - sx * sx / count, vy = syy - sy * sy / count;
    if (vx > 0 && vy > 0) m.correlation = cov / std::sqrt(vx * vy);
    if (sn > 0) m.error = std::sqrt(se / sn);
  }
  return m;
}

}  // namespace tactip
