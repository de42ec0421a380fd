#include "sensors/camera.h"

#include <cmath>

#include <fmt/format.h>

namespace tactip {

namespace {

// Refuses a focal length outside kMinFocalPerPx..kMaxFocalPerPx times the image size.
void CheckFocal(const std::string& key, double f_px, const std::string& size_key, int size_px) {
  // Divided, not multiplied by 0.1, so that the bound prints exactly as it is checked.
  const double lo = size_px / (1.0 / CameraConfig::kMinFocalPerPx), hi = CameraConfig::kMaxFocalPerPx * size_px;
  if (f_px < lo || f_px > hi) {
    FailRule(key, f_px,
             fmt::format("must be {} to {} x {} ({} to {} px for {} px: a field of view of 157 to 2.9 degrees)",
                         CameraConfig::kMinFocalPerPx, CameraConfig::kMaxFocalPerPx, size_key,
                         config_detail::FormatReal(lo), config_detail::FormatReal(hi), size_px));
  }
}

// Refuses a principal point outside the image.
void CheckPrincipal(const std::string& key, double c_px, const std::string& size_key, int size_px) {
  if (c_px < 0.0 || c_px > size_px) {
    FailRule(key, c_px, fmt::format("must be inside the image, 0 to {} = {} px", size_key, size_px));
  }
}

}  // namespace

void CameraConfig::ValidateRules() const {
  CheckFocal("sensor.fx_px", fx_px, "sensor.width_px", width_px);
  CheckFocal("sensor.fy_px", fy_px, "sensor.height_px", height_px);
  CheckPrincipal("sensor.cx_px", cx_px, "sensor.width_px", width_px);
  CheckPrincipal("sensor.cy_px", cy_px, "sensor.height_px", height_px);
}

void ExternalCameraConfig::ValidateIntrinsics(const CameraConfig& image) const {
  CheckFocal("external.f_px", f_px, "sensor.width_px", image.width_px);
  CheckPrincipal("external.cx_px", cx_px, "sensor.width_px", image.width_px);
  CheckPrincipal("external.cy_px", cy_px, "sensor.height_px", image.height_px);
}

std::array<double, 2> PinholeCamera::Project(const std::array<double, 3>& p) const {
  // Depth along the axis from the optical centre, then the pinhole model.
  const double depth = p[0] + cfg_.camera_offset_mm * 1e-3;
  return {cfg_.cx_px + cfg_.fx_px * p[1] / depth, cfg_.cy_px - cfg_.fy_px * p[2] / depth};
}

double PinholeCamera::ImageGain(const std::array<double, 3>& p) const {
  // u = cx + fx y / d, v = cy - fy z / d with d = x + offset: du/dp = fx (-y / d^2, 1 / d, 0),
  // dv/dp = fy (z / d^2, 0, -1 / d).
  const double d = p[0] + cfg_.camera_offset_mm * 1e-3;
  const double d2 = d * d;
  const double gu = cfg_.fx_px * cfg_.fx_px * (p[1] * p[1] / (d2 * d2) + 1.0 / d2);
  const double gv = cfg_.fy_px * cfg_.fy_px * (p[2] * p[2] / (d2 * d2) + 1.0 / d2);
  return std::sqrt(gu + gv);
}

std::array<double, 2> ExternalCamera::Project(const std::array<double, 3>& p) const {
  const double depth = cam_x_ - p[0];
  return {cfg_.cx_px - cfg_.f_px * p[1] / depth, cfg_.cy_px - cfg_.f_px * p[2] / depth};
}

long long FrameStep(long long k, double rate_hz, double timestep_s) {
  return std::llround(static_cast<double>(k) / (rate_hz * timestep_s));
}

}  // namespace tactip
