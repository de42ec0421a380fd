#include "sensors/marker_labels.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

namespace tactip {

namespace {

// `height_m` at time `t`, linearly between the frames (clamped to the first and last).
double HeightAt(const std::vector<double>& time_s, const std::vector<double>& height_m, double t) {
  if (t <= time_s.front()) return height_m.front();
  if (t >= time_s.back()) return height_m.back();
  const size_t k = static_cast<size_t>(std::upper_bound(time_s.begin(), time_s.end(), t) - time_s.begin());
  const double a = (t - time_s[k - 1]) / (time_s[k] - time_s[k - 1]);
  return height_m[k - 1] + a * (height_m[k] - height_m[k - 1]);
}

}  // namespace

double MarkerOnset(const std::vector<double>& time_s, const std::vector<double>& height_m, const HoldSpan& hold,
                   const MarkerCameraConfig& cfg, std::uint64_t seed) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double hold_end_s = hold.end_s;
  if (time_s.size() < 2 || height_m.size() != time_s.size() || !std::isfinite(hold_end_s)) return nan;
  const double reference_from = std::max(hold.start_s, hold_end_s - cfg.reference_s);
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> jitter(0.0, 1.0);
  const double period = 1.0 / cfg.frame_rate_hz;
  const double phase = std::uniform_real_distribution<double>(0.0, period)(rng);
  // One marker frame: the height tracked to the camera's pixels, in mm.
  const auto measure = [&](double t) {
    const double px = HeightAt(time_s, height_m, t) * 1e3 / cfg.mm_per_px + cfg.jitter_px * jitter(rng);
    return std::round(px) * cfg.mm_per_px;
  };
  double sum = 0.0;
  int n = 0;
  double t = time_s.front() + phase;
  for (; t < hold_end_s; t += period) {
    if (t < reference_from) continue;
    sum += measure(t);
    ++n;
  }
  for (; t <= time_s.back(); t += period) {
    const double mm = measure(t);
    if (n == 0) {  // no held frame before the hold's end: the first after it is the reference
      sum = mm;
      n = 1;
      continue;
    }
    if (std::abs(mm - sum / n) >= cfg.threshold_mm) return t;
  }
  return nan;
}

}  // namespace tactip
