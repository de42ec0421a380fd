#include "sensors/tactile_image.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include <fmt/format.h>
#include <opencv2/imgproc.hpp>

namespace tactip {

namespace {

/// Fractional bits of the sub-pixel coordinates cv::circle draws with (1/16 px).
constexpr int kSubPixelBits = 4;
constexpr double kSubPixelScale = 1 << kSubPixelBits;

}  // namespace

void TactileImageConfig::ValidateRules() const {
  if (threshold_min + threshold_step >= threshold_max) {
    FailRule("images.threshold_max", threshold_max,
             fmt::format("must be > images.threshold_min + images.threshold_step = {} (a blob must show at two "
                         "thresholds)",
                         threshold_min + threshold_step));
  }
  if (min_blob_area_px >= max_blob_area_px) {
    FailRule("images.max_blob_area_px", max_blob_area_px,
             fmt::format("must be > images.min_blob_area_px = {}", min_blob_area_px));
  }
  if (pin_grey <= skin_grey) {
    FailRule("images.pin_grey", pin_grey, fmt::format("must be > images.skin_grey = {} (white markers on a dark "
                                                      "skin)",
                                                      skin_grey));
  }
}

double TipRadiusPx(const CameraConfig& camera, double pin_tip_radius_mm, double depth_m) {
  return 0.5 * (camera.fx_px + camera.fy_px) * pin_tip_radius_mm * 1e-3 / depth_m;
}

bool TipInImage(const CameraConfig& camera, double pin_tip_radius_mm, const std::array<double, 3>& p) {
  const double depth = p[0] + camera.camera_offset_mm * 1e-3;
  if (depth <= 0.0) return false;
  const auto uv = PinholeCamera(camera).Project(p);
  const double r = TipRadiusPx(camera, pin_tip_radius_mm, depth);
  // Pixel centres run from 0 to size - 1; the disc must end inside them.
  return uv[0] - r >= 0.0 && uv[1] - r >= 0.0 && uv[0] + r <= camera.width_px - 1.0 && uv[1] + r <= camera.height_px - 1.0;
}

TactileImageRenderer::TactileImageRenderer(const TactileImageConfig& cfg, const CameraConfig& camera,
                                           std::uint64_t noise_seed)
    : cfg_(cfg), camera_(camera), rng_(noise_seed) {}

const cv::Mat& TactileImageRenderer::Render(const std::vector<float>& px, const std::vector<float>& pos_m) {
  const size_t n = px.size() / 2;
  if (px.size() != 2 * n || pos_m.size() != 3 * n) {
    throw std::invalid_argument(fmt::format("TactileImageRenderer: {} image coordinates for {} tip coordinates",
                                            px.size(), pos_m.size()));
  }
  // The dark skin, then each tip as an anti-aliased disc at its sub-pixel position: radius
  // from its depth, brightness falling off as cos^p of its ray's angle from the axis.
  drawn_.create(camera_.height_px, camera_.width_px, CV_8UC1);
  drawn_.setTo(cv::Scalar(cfg_.skin_grey));
  const double offset_m = camera_.camera_offset_mm * 1e-3;
  for (size_t i = 0; i < n; ++i) {
    const double depth = pos_m[3 * i] + offset_m;
    if (depth <= 0.0) continue;  // behind the camera: not seen
    const double lateral = std::hypot(pos_m[3 * i + 1], pos_m[3 * i + 2]);
    const double cos_ray = depth / std::hypot(depth, lateral);
    const double grey = cfg_.skin_grey + (cfg_.pin_grey - cfg_.skin_grey) * std::pow(cos_ray, cfg_.rim_falloff_power);
    const cv::Point centre(static_cast<int>(std::lround(px[2 * i] * kSubPixelScale)),
                           static_cast<int>(std::lround(px[2 * i + 1] * kSubPixelScale)));
    const int radius = static_cast<int>(std::lround(TipRadiusPx(camera_, cfg_.pin_tip_radius_mm, depth) * kSubPixelScale));
    cv::circle(drawn_, centre, radius, cv::Scalar(grey), cv::FILLED, cv::LINE_AA, kSubPixelBits);
  }
  // Optics: Gaussian blur.
  drawn_.convertTo(blurred_, CV_32F);
  if (cfg_.blur_sigma_px > 0.0) cv::GaussianBlur(blurred_, blurred_, cv::Size(0, 0), cfg_.blur_sigma_px);
  // Sensor: read noise, then quantisation to uint8 (rounded, saturated).
  if (cfg_.noise_grey > 0.0) {
    noise_.create(blurred_.size(), CV_32F);
    rng_.fill(noise_, cv::RNG::NORMAL, 0.0, cfg_.noise_grey);
    blurred_ += noise_;
  }
  blurred_.convertTo(image_, CV_8U);
  return image_;
}

}  // namespace tactip
