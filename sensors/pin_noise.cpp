#include "sensors/pin_noise.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace tactip {

namespace {

/// Seed of the structured parts' stream, derived from the camera's seed (SplitMix64's
/// increment), so that the independent stream is the independent model's.
constexpr std::uint64_t kStructuredStream = 0x9E3779B97F4A7C15ULL;
/// The neighbour kernel is cut where its weight falls below exp(-kKernelCut^2 / 2).
constexpr double kKernelCut = 3.0;

}  // namespace

double MeanNearestNeighbourPx(const std::vector<float>& px) {
  const size_t n = px.size() / 2;
  if (n < 2) return 0.0;
  double sum = 0.0;
  for (size_t i = 0; i < n; ++i) {
    double best = std::numeric_limits<double>::infinity();
    for (size_t j = 0; j < n; ++j) {
      if (j == i) continue;
      best = std::min(best, static_cast<double>(std::hypot(px[2 * i] - px[2 * j], px[2 * i + 1] - px[2 * j + 1])));
    }
    sum += best;
  }
  return sum / static_cast<double>(n);
}

DetectionNoise::DetectionNoise(const CameraConfig& cfg, std::uint64_t seed)
    : cfg_(cfg), rng_(seed), structured_(seed ^ kStructuredStream), structured_model_(cfg.noise_model == "structured") {
  if (!structured_model_) return;
  a_ = cfg.common_time_s > 0.0 ? std::exp(-1.0 / (cfg.frame_rate_hz * cfg.common_time_s)) : 0.0;
  shift_u_.std = shift_v_.std = cfg.common_shift_px;
  turn_.std = cfg.common_rotation_deg * std::numbers::pi / 180.0;
  scale_.std = cfg.common_scale_pct * 1e-2;
}

void DetectionNoise::BuildKernel(const std::vector<float>& px) {
  // Gaussian weights of std local_length_pitch pitches over the pins within kKernelCut of
  // it, scaled to unit sum of squares: the field then has the configured std at every pin,
  // and neighbours at distance d correlate by about exp(-d^2 / (4 l^2)).
  const size_t n = px.size() / 2;
  pitch_px_ = MeanNearestNeighbourPx(px);
  const double l = cfg_.local_length_pitch * pitch_px_;
  offsets_.assign(1, 0);
  neighbours_.clear();
  weights_.clear();
  for (size_t i = 0; i < n; ++i) {
    double sum2 = 0.0;
    const size_t row = weights_.size();
    for (size_t j = 0; j < n; ++j) {
      const double d = std::hypot(static_cast<double>(px[2 * i] - px[2 * j]), static_cast<double>(px[2 * i + 1] - px[2 * j + 1]));
      if (j != i && (l <= 0.0 || d > kKernelCut * l)) continue;
      const double w = l > 0.0 ? std::exp(-0.5 * d * d / (l * l)) : 1.0;
      neighbours_.push_back(static_cast<int>(j));
      weights_.push_back(w);
      sum2 += w * w;
    }
    const double norm = 1.0 / std::sqrt(sum2);
    for (size_t k = row; k < weights_.size(); ++k) weights_[k] *= norm;
    offsets_.push_back(static_cast<int>(weights_.size()));
  }
  white_.assign(2 * n, 0.0);
}

void DetectionNoise::StepCommon() {
  // Stationary from the first frame: x = a x + sqrt(1 - a^2) std xi.
  const double keep = started_ ? a_ : 0.0;
  const double innovation = std::sqrt(1.0 - keep * keep);
  for (Ar1* c : {&shift_u_, &shift_v_, &turn_, &scale_}) c->x = keep * c->x + innovation * c->std * structured_.Normal();
  started_ = true;
}

void DetectionNoise::AddStructured(std::vector<float>& px) {
  const size_t n = px.size() / 2;
  StepCommon();
  for (double& w : white_) w = structured_.Normal();
  for (size_t i = 0; i < n; ++i) {
    // The similarity about the principal point, to first order in the angle and the scale.
    const double u = px[2 * i] - cfg_.cx_px, v = px[2 * i + 1] - cfg_.cy_px;
    double du = shift_u_.x + scale_.x * u - turn_.x * v;
    double dv = shift_v_.x + scale_.x * v + turn_.x * u;
    double fu = 0.0, fv = 0.0;
    for (int k = offsets_[i]; k < offsets_[i + 1]; ++k) {
      fu += weights_[k] * white_[2 * neighbours_[k]];
      fv += weights_[k] * white_[2 * neighbours_[k] + 1];
    }
    du += cfg_.local_noise_px * fu;
    dv += cfg_.local_noise_px * fv;
    px[2 * i] += static_cast<float>(du);
    px[2 * i + 1] += static_cast<float>(dv);
  }
}

void DetectionNoise::Apply(std::vector<float>& px, std::vector<std::uint8_t>& valid,
                           const std::vector<float>& prev_px) {
  if (structured_model_) {
    if (offsets_.empty()) BuildKernel(px);
    AddStructured(px);
  }
  const size_t n = valid.size();
  for (size_t i = 0; i < n; ++i) {
    // Draw both noise values and the dropout for every pin, so the random stream does
    // not depend on which pins were missed.
    const double nu = rng_.Normal() * cfg_.pixel_noise_px;
    const double nv = rng_.Normal() * cfg_.pixel_noise_px;
    const bool missed = rng_.Uniform() < cfg_.dropout_prob;
    px[2 * i] += static_cast<float>(nu);
    px[2 * i + 1] += static_cast<float>(nv);
    valid[i] = missed ? 0 : 1;
    if (missed && !prev_px.empty()) {
      px[2 * i] = prev_px[2 * i];
      px[2 * i + 1] = prev_px[2 * i + 1];
    }
  }
}

}  // namespace tactip
