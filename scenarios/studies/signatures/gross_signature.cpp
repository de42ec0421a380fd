#include "scenarios/studies/signatures/gross_signature.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <vector>

#include "scenarios/studies/run_signals/run_signals.h"
#include "sim/base/nan.h"

namespace tactip {

namespace {


// Consecutive frames from `first` whose unsmoothed mean pin speed exceeds `level_px`.
int FramesAbove(const RunRecord& run, const SensorRecord& sensor, size_t first, double level_px) {
  int width = 0;
  for (size_t f = first; f < run.frames(); ++f) {
    const double s = MeanPinSpeedPx(sensor, f);
    if (!(s > level_px)) break;  // also stops at a frame without pin velocities (NaN)
    ++width;
  }
  return width;
}

// Time from the onset to the first frame at or after `first` with no pin in contact; NaN if none.
double ContactLostAfterS(const RunRecord& run, const SensorRecord& sensor, size_t first, double onset_s) {
  const auto n = static_cast<size_t>(sensor.n_pins);
  for (size_t f = first; f < run.frames(); ++f) {
    bool any = false;
    for (size_t i = 0; i < n && !any; ++i) any = sensor.pin_contact[f * n + i] != 0;
    if (!any) return run.time[f] - onset_s;
  }
  return kNaN;
}

// Pin i's mean image position over the frames [first, end) in which it is valid; nullopt if
// it is valid in none of them.
std::optional<std::array<double, 2>> MeanPinPositionPx(const SensorRecord& sensor, size_t first, size_t end,
                                                       size_t i) {
  const auto n = static_cast<size_t>(sensor.n_pins);
  double u = 0.0, v = 0.0;
  int count = 0;
  for (size_t f = first; f < end; ++f) {
    if (sensor.valid[f * n + i] == 0) continue;
    u += sensor.pos_px[(f * n + i) * 2];
    v += sensor.pos_px[(f * n + i) * 2 + 1];
    ++count;
  }
  if (count == 0) return std::nullopt;
  return std::array<double, 2>{u / count, v / count};
}

// Whether both step windows around `onset_frame` lie in the recording.
bool StepWindowsRecorded(const RunRecord& run, size_t onset_frame) {
  return onset_frame >= kStepBeforeFrames && onset_frame + kStepAfterEndFrame <= run.frames();
}

// GrossSignature::step_px of the onset frame.
double PatternStepPx(const RunRecord& run, const SensorRecord& sensor, size_t onset_frame) {
  if (!StepWindowsRecorded(run, onset_frame)) return kNaN;
  double du = 0.0, dv = 0.0;
  int pins = 0;
  for (size_t i = 0; i < static_cast<size_t>(sensor.n_pins); ++i) {
    const auto before = MeanPinPositionPx(sensor, onset_frame - kStepBeforeFrames, onset_frame, i);
    const auto after =
        MeanPinPositionPx(sensor, onset_frame + kStepAfterFirstFrame, onset_frame + kStepAfterEndFrame, i);
    if (!before || !after) continue;
    du += (*after)[0] - (*before)[0];
    dv += (*after)[1] - (*before)[1];
    ++pins;
  }
  return pins == 0 ? kNaN : std::hypot(du / pins, dv / pins);
}

// GrossSignature::after_w5_px of the onset frame.
double SpeedW5AfterSpikePx(const RunRecord& run, const SensorRecord& sensor, size_t onset_frame) {
  if (!StepWindowsRecorded(run, onset_frame)) return kNaN;
  double sum = 0.0;
  int frames = 0;
  for (size_t f = onset_frame + kStepAfterFirstFrame; f < onset_frame + kStepAfterEndFrame; ++f) {
    const double s = MeanPinSpeedPx(sensor, f, kSmoothingFrames);
    if (std::isnan(s)) continue;
    sum += s;
    ++frames;
  }
  return frames == 0 ? kNaN : sum / frames;
}

}  // namespace

double ColinearFraction(const SensorRecord& sensor, size_t f, double pin_level_px) {
  // The moving pins' velocities and their sum.
  std::vector<std::array<double, 2>> moving;
  double su = 0.0, sv = 0.0;
  for (size_t i = 0; i < static_cast<size_t>(sensor.n_pins); ++i) {
    const auto v = PinVelocityPx(sensor, f, i);
    if (!v || !(std::hypot((*v)[0], (*v)[1]) > pin_level_px)) continue;
    moving.push_back(*v);
    su += (*v)[0];
    sv += (*v)[1];
  }
  const double sum_norm = std::hypot(su, sv);
  if (moving.empty() || sum_norm == 0.0) return kNaN;
  // Share within the cone around the mean direction.
  const double cos_limit = std::cos(kColinearHalfAngleDeg * std::numbers::pi / 180.0);
  int inside = 0;
  for (const auto& v : moving) {
    if ((v[0] * su + v[1] * sv) / (std::hypot(v[0], v[1]) * sum_norm) >= cos_limit) ++inside;
  }
  return static_cast<double>(inside) / static_cast<double>(moving.size());
}

std::optional<GrossSignature> MeasureGrossSignature(const RunRecord& run, const SensorRecord& sensor,
                                                    double held_window_s) {
  const double onset_s = RunAttr(run, "gross_slip_onset_s");
  if (std::isnan(onset_s)) return std::nullopt;
  GrossSignature g;
  g.noise = MeasureHeldNoise(run, sensor, held_window_s);
  g.onset_frame = static_cast<int>(std::max<size_t>(1, FrameAt(run, onset_s)));
  const auto onset_frame = static_cast<size_t>(g.onset_frame);
  // Spike start and width against the held noise level; peaks unsmoothed and smoothed.
  const bool onset_above = onset_frame < run.frames() && MeanPinSpeedPx(sensor, onset_frame) > g.noise.Level();
  const size_t start = onset_frame + (onset_above ? 0 : 1);
  g.spike_start_frame = static_cast<int>(start);
  g.spike_width_frames = std::isnan(g.noise.Level()) ? -1 : FramesAbove(run, sensor, start, g.noise.Level());
  g.spike_peak_px = PeakMeanPinSpeedPx(run, sensor, onset_s, kSpikePeakSpanS);
  g.spike_peak_w5_px = PeakMeanPinSpeedPx(run, sensor, onset_s, kSpikePeakSpanS, kSmoothingFrames);
  // Co-linearity at the spike's start and a few frames later (NaN past the recording).
  const double pin_level = g.noise.PinLevel();
  const size_t later = start + kColinearLaterFrames;
  g.colinear_onset = start < run.frames() ? ColinearFraction(sensor, start, pin_level) : kNaN;
  g.colinear_later = later < run.frames() ? ColinearFraction(sensor, later, pin_level) : kNaN;
  g.contact_lost_s = ContactLostAfterS(run, sensor, onset_frame, onset_s);
  g.step_px = PatternStepPx(run, sensor, onset_frame);
  g.after_w5_px = SpeedW5AfterSpikePx(run, sensor, onset_frame);
  return g;
}

}  // namespace tactip
