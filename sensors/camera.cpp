#include "sensors/camera.h"

#include <cmath>

namespace tactip {

std::array<double, 2> PinholeCamera::Project(const std::array<double, 3>& p) const {
  // Depth along the axis from the optical centre, then the pinhole model.
  const double depth = p[0] + cfg_.camera_offset_mm * 1e-3;
  return {cfg_.cx_px + cfg_.fx_px * p[1] / depth, cfg_.cy_px - cfg_.fy_px * p[2] / depth};
}

std::array<double, 2> ExternalCamera::Project(const std::array<double, 3>& p) const {
  const double depth = cam_x_ - p[0];
  return {cfg_.cx_px - cfg_.f_px * p[1] / depth, cfg_.cy_px - cfg_.f_px * p[2] / depth};
}

long long FrameStep(long long k, double rate_hz, double timestep_s) {
  return std::llround(static_cast<double>(k) / (rate_hz * timestep_s));
}

void DetectionNoise::Apply(std::vector<float>& px, std::vector<std::uint8_t>& valid,
                           const std::vector<float>& prev_px) {
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
