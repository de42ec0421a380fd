#include "scenarios/studies/signatures/held_noise.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "scenarios/studies/run_signals/run_signals.h"
#include "sim/base/number_text.h"
#include "sim/config.h"

namespace tactip {

namespace {

// Mean and sample standard deviation (NaN for fewer than two values).
std::pair<double, double> MeanAndStd(const std::vector<double>& v) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  if (v.size() < 2) return {kNaN, kNaN};
  double sum = 0.0;
  for (double x : v) sum += x;
  const double mean = sum / static_cast<double>(v.size());
  double sq = 0.0;
  for (double x : v) sq += (x - mean) * (x - mean);
  return {mean, std::sqrt(sq / static_cast<double>(v.size() - 1))};
}

}  // namespace

double HeldWindowS(const DatasetHeader& header) {
  // Best effort: a config without a readable, positive rail.hold_s keeps the default.
  try {
    const FlatConfig config = FlattenYaml(header.config_yaml, "config_yaml");
    const auto it = config.find("rail.hold_s");
    double hold_s = 0.0;
    if (it != config.end() && ParseWhole(it->second, hold_s) && hold_s > 0.0) return std::min(hold_s, kHeldWindowS);
  } catch (const InputError&) {
  }
  return kHeldWindowS;
}

HeldNoise MeasureHeldNoise(const RunRecord& run, const SensorRecord& sensor, double window_s) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  HeldNoise h{0, kNaN, kNaN, kNaN, kNaN, kNaN};
  // The window's end: the retraction start, else just before the onset.
  double end_s = RunAttr(run, "retract_start_s");
  if (std::isnan(end_s)) end_s = RunAttr(run, "gross_slip_onset_s") - kHeldGapBeforeOnsetS;
  if (std::isnan(end_s)) return h;
  const size_t first = std::max<size_t>(1, FrameAt(run, end_s - window_s)), end = FrameAt(run, end_s);

  // Per-frame mean speeds (unsmoothed and W = 5) and every pin's unsmoothed speed.
  std::vector<double> mean_speeds, mean_w5, pin_speeds;
  for (size_t f = first; f < end; ++f) {
    const double s = MeanPinSpeedPx(sensor, f);
    if (std::isnan(s)) continue;
    mean_speeds.push_back(s);
    mean_w5.push_back(MeanPinSpeedPx(sensor, f, kSmoothingFrames));
    for (size_t i = 0; i < static_cast<size_t>(sensor.n_pins); ++i) {
      if (const auto v = PinVelocityPx(sensor, f, i)) pin_speeds.push_back(std::hypot((*v)[0], (*v)[1]));
    }
  }
  if (mean_speeds.size() < 2) return h;
  h.frames = static_cast<int>(mean_speeds.size());
  std::tie(h.mean_speed_px, h.std_speed_px) = MeanAndStd(mean_speeds);
  h.mean_speed_w5_px = MeanAndStd(mean_w5).first;
  std::tie(h.pin_mean_px, h.pin_std_px) = MeanAndStd(pin_speeds);
  return h;
}

}  // namespace tactip
