#include "scenarios/studies/noise/noise_structure.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>

#include <fmt/format.h>

#include "scenarios/studies/run_signals/run_signals.h"
#include "scenarios/studies/signatures/held_noise.h"
#include "sensors/pin_noise.h"
#include "sim/base/nan.h"

namespace tactip {

namespace {

/// Fewest frames and pins the figures are measured on.
constexpr int kMinFrames = 3;
constexpr int kMinPins = 3;
/// Neighbour bands of the residual correlation, in pattern pitches.
constexpr double kNeighbourPitches = 1.3, kNextPitches = 2.3;
/// Most frame pairs the random-pair step is averaged over (a whole recording has many).
constexpr size_t kMaxFramePairs = 20000;

using Vec2 = std::array<double, 2>;

/// The still frames' positions of the pins valid in all of them, each pin's straight line
/// over the window taken out (a held skin still settles slowly; the noise is what is left):
/// mean position per pin and the deviation from its line frame by frame.
struct Deviations {
  std::vector<Vec2> mean;               // per pin
  std::vector<std::vector<Vec2>> dev;   // [frame][pin]
};

// The pins valid in every frame of the window.
std::vector<size_t> AlwaysValid(const SensorRecord& s, const NoiseWindow& w) {
  const size_t n = static_cast<size_t>(s.n_pins);
  std::vector<size_t> pins;
  for (size_t i = 0; i < n; ++i) {
    bool always = true;
    for (size_t f = w.first; f < w.end && always; ++f) always = s.valid[f * n + i] != 0;
    if (always) pins.push_back(i);
  }
  return pins;
}

Deviations CollectDeviations(const SensorRecord& s, const NoiseWindow& w) {
  const size_t n = static_cast<size_t>(s.n_pins), frames = w.end - w.first;
  const std::vector<size_t> pins = AlwaysValid(s, w);
  // Least-squares line per pin and coordinate over the frame index k = 0 .. frames-1.
  const double k_mean = 0.5 * static_cast<double>(frames - 1);
  double k_var = 0.0;
  for (size_t k = 0; k < frames; ++k) k_var += (k - k_mean) * (k - k_mean);
  Deviations d;
  d.mean.assign(pins.size(), {0.0, 0.0});
  std::vector<Vec2> slope(pins.size(), {0.0, 0.0});
  const auto at = [&](size_t k, size_t p, int c) { return static_cast<double>(s.pos_px[2 * ((w.first + k) * n + pins[p]) + c]); };
  for (size_t p = 0; p < pins.size(); ++p) {
    for (size_t k = 0; k < frames; ++k) {
      for (int c = 0; c < 2; ++c) {
        d.mean[p][c] += at(k, p, c) / static_cast<double>(frames);
        slope[p][c] += k_var > 0.0 ? at(k, p, c) * (k - k_mean) / k_var : 0.0;
      }
    }
  }
  for (size_t k = 0; k < frames; ++k) {
    std::vector<Vec2> dev(pins.size());
    for (size_t p = 0; p < pins.size(); ++p) {
      for (int c = 0; c < 2; ++c) dev[p][c] = at(k, p, c) - d.mean[p][c] - slope[p][c] * (k - k_mean);
    }
    d.dev.push_back(std::move(dev));
  }
  return d;
}

double Norm2(const Vec2& v) { return v[0] * v[0] + v[1] * v[1]; }

/// Mean distance from the centre of the outer ring of centred positions `q`: the 6k
/// outermost pins of a hexagonal pattern of 1 + 3k(k+1) pins (ring k), else the pins at
/// >= 0.9 of the largest distance.
double OuterRingRadius(const std::vector<Vec2>& q) {
  std::vector<double> r;
  for (const Vec2& v : q) r.push_back(std::sqrt(Norm2(v)));
  std::sort(r.begin(), r.end(), std::greater<>());
  size_t ring = 0;
  for (size_t k = 1; 1 + 3 * k * (k + 1) <= r.size(); ++k) {
    if (1 + 3 * k * (k + 1) == r.size()) ring = 6 * k;
  }
  if (ring == 0) {
    while (ring < r.size() && r[ring] >= 0.9 * r.front()) ++ring;
  }
  double sum = 0.0;
  for (size_t i = 0; i < ring; ++i) sum += r[i];
  return sum / static_cast<double>(ring);
}

/// Per frame: the mean deviation (the common mode) and the residual after one similarity
/// about the pattern's centre (least squares; translation, scale and rotation are
/// orthogonal there because the centred positions q sum to zero and q . q_perp = 0).
struct Fits {
  std::vector<Vec2> common;                // [frame]
  std::vector<std::vector<Vec2>> residual; // [frame][pin]
  double pattern_radius_px = 0.0;
};

Fits FitSimilarities(const Deviations& d) {
  Vec2 centre{0.0, 0.0};
  for (const Vec2& m : d.mean) centre = {centre[0] + m[0] / d.mean.size(), centre[1] + m[1] / d.mean.size()};
  std::vector<Vec2> q;
  double q2 = 0.0;
  for (const Vec2& m : d.mean) {
    q.push_back({m[0] - centre[0], m[1] - centre[1]});
    q2 += Norm2(q.back());
  }
  Fits fits;
  fits.pattern_radius_px = OuterRingRadius(q);
  for (const auto& dev : d.dev) {
    Vec2 t{0.0, 0.0};
    double scale = 0.0, turn = 0.0;
    for (size_t k = 0; k < dev.size(); ++k) {
      t = {t[0] + dev[k][0] / dev.size(), t[1] + dev[k][1] / dev.size()};
      scale += (dev[k][0] * q[k][0] + dev[k][1] * q[k][1]) / q2;
      turn += (-dev[k][0] * q[k][1] + dev[k][1] * q[k][0]) / q2;
    }
    std::vector<Vec2> r(dev.size());
    for (size_t k = 0; k < dev.size(); ++k) {
      r[k] = {dev[k][0] - t[0] - scale * q[k][0] + turn * q[k][1], dev[k][1] - t[1] - scale * q[k][1] - turn * q[k][0]};
    }
    fits.common.push_back(t);
    fits.residual.push_back(std::move(r));
  }
  return fits;
}

/// The spread figures: per-pin std, common mode, the shares the fits remove, the residual.
void SpreadFigures(const Deviations& d, const Fits& fits, NoiseStructure& out) {
  const double frames = static_cast<double>(d.dev.size()), pins = static_cast<double>(d.mean.size());
  double total = 0.0, after_shift = 0.0, after_similarity = 0.0, common = 0.0;
  for (size_t f = 0; f < d.dev.size(); ++f) {
    common += Norm2(fits.common[f]);
    for (size_t k = 0; k < d.mean.size(); ++k) {
      total += Norm2(d.dev[f][k]);
      after_shift += Norm2({d.dev[f][k][0] - fits.common[f][0], d.dev[f][k][1] - fits.common[f][1]});
      after_similarity += Norm2(fits.residual[f][k]);
    }
  }
  // Sample variances per coordinate: each pin's line (mean and slope) is estimated, two
  // degrees of freedom.
  const double dof = 2.0 * (frames - 2.0);
  out.pin_std_px = std::sqrt(total / (pins * dof));
  out.common_std_px = std::sqrt(common / dof);
  out.common_ratio = out.common_std_px / (out.pin_std_px / std::sqrt(pins));
  out.translation_share = 1.0 - after_shift / total;
  out.similarity_share = 1.0 - after_similarity / total;
  out.residual_std_px = std::sqrt(after_similarity / (pins * dof));
}

/// Pooled correlation of the residual vectors of pin pairs in the two neighbour bands.
void NeighbourFigures(const Deviations& d, const Fits& fits, NoiseStructure& out) {
  std::vector<float> rest;
  for (const Vec2& m : d.mean) rest.insert(rest.end(), {static_cast<float>(m[0]), static_cast<float>(m[1])});
  const double pitch = MeanNearestNeighbourPx(rest);
  std::array<double, 2> cross{0.0, 0.0}, power{0.0, 0.0};
  for (size_t i = 0; i < d.mean.size(); ++i) {
    for (size_t j = i + 1; j < d.mean.size(); ++j) {
      const double dist = std::hypot(d.mean[i][0] - d.mean[j][0], d.mean[i][1] - d.mean[j][1]) / pitch;
      const int band = dist <= kNeighbourPitches ? 0 : dist <= kNextPitches ? 1 : -1;
      if (band < 0) continue;
      for (const auto& r : fits.residual) {
        cross[band] += r[i][0] * r[j][0] + r[i][1] * r[j][1];
        power[band] += 0.5 * (Norm2(r[i]) + Norm2(r[j]));
      }
    }
  }
  out.neighbour_corr = power[0] > 0.0 ? cross[0] / power[0] : kNaN;
  out.next_corr = power[1] > 0.0 ? cross[1] / power[1] : kNaN;
}

/// How slowly the noise varies: the common mode's lag-1 autocorrelation and the mean step
/// between consecutive frames over that between any two frames of the window (every pair up
/// to kMaxFramePairs pairs, else every k-th of them). A step between detrended positions is
/// the step between their deviations.
void TemporalFigures(const Deviations& d, const Fits& fits, NoiseStructure& out) {
  double lag = 0.0, power = 0.0;
  for (size_t f = 0; f < fits.common.size(); ++f) {
    power += Norm2(fits.common[f]);
    if (f > 0) lag += fits.common[f][0] * fits.common[f - 1][0] + fits.common[f][1] * fits.common[f - 1][1];
  }
  out.common_lag1 = power > 0.0 ? lag / power : kNaN;
  const auto mean_step = [&](size_t f, size_t g) {
    double sum = 0.0;
    for (size_t k = 0; k < d.mean.size(); ++k) {
      sum += std::hypot(d.dev[g][k][0] - d.dev[f][k][0], d.dev[g][k][1] - d.dev[f][k][1]);
    }
    return sum / static_cast<double>(d.mean.size());
  };
  const size_t frames = d.dev.size(), pairs = frames * (frames - 1) / 2;
  const size_t stride = std::max<size_t>(1, pairs / kMaxFramePairs);
  double consecutive = 0.0, any = 0.0;
  size_t n_any = 0, pair = 0;
  for (size_t f = 0; f < frames; ++f) {
    if (f + 1 < frames) consecutive += mean_step(f, f + 1);
    for (size_t g = f + 1; g < frames; ++g, ++pair) {
      if (pair % stride != 0) continue;
      any += mean_step(f, g);
      ++n_any;
    }
  }
  out.consecutive_over_random = (consecutive / static_cast<double>(frames - 1)) / (any / static_cast<double>(n_any));
}

/// Mean over the window's frames of the mean pin speed at W = 1 and W = 5, each over the
/// frames whose whole window lies in the still frames.
void SpeedFigures(const SensorRecord& s, const NoiseWindow& w, NoiseStructure& out) {
  for (const int window : {1, kSmoothingFrames}) {
    double sum = 0.0;
    int count = 0;
    for (size_t f = w.first + static_cast<size_t>(window); f < w.end; ++f) {
      const double v = MeanPinSpeedPx(s, f, window);
      if (std::isnan(v)) continue;
      sum += v;
      ++count;
    }
    (window == 1 ? out.speed_w1_px : out.speed_w5_px) = count > 0 ? sum / count : kNaN;
  }
}

}  // namespace

NoiseWindow StillFrames(const RunRecord& run, double held_window_s) {
  double end_s = RunAttr(run, "retract_start_s");
  if (std::isnan(end_s)) end_s = RunAttr(run, "gross_slip_onset_s") - kHeldGapBeforeOnsetS;
  if (std::isnan(end_s)) return {0, run.frames(), false};
  return {FrameAt(run, end_s - held_window_s), FrameAt(run, end_s), true};
}

NoiseStructure MeasureNoiseStructure(const RunRecord& run, const SensorRecord& sensor, const NoiseWindow& window,
                                     int run_index) {
  NoiseStructure out;
  out.run = run_index;
  out.sensor = sensor.name;
  out.held = window.held;
  out.frames = static_cast<int>(window.end - window.first);
  sensor.CheckPinArrays(run.frames(), "noise report");
  const Deviations d = CollectDeviations(sensor, window);
  out.pins = static_cast<int>(d.mean.size());
  if (out.frames < kMinFrames || out.pins < kMinPins) {
    for (double* v : {&out.pattern_radius_px, &out.pin_std_px, &out.common_std_px, &out.common_ratio, &out.translation_share,
                      &out.similarity_share, &out.residual_std_px, &out.neighbour_corr, &out.next_corr,
                      &out.common_lag1, &out.consecutive_over_random, &out.speed_w1_px, &out.speed_w5_px}) {
      *v = kNaN;
    }
    return out;
  }
  const Fits fits = FitSimilarities(d);
  out.pattern_radius_px = fits.pattern_radius_px;
  SpreadFigures(d, fits, out);
  NeighbourFigures(d, fits, out);
  TemporalFigures(d, fits, out);
  SpeedFigures(sensor, window, out);
  return out;
}

}  // namespace tactip
