// Test support: a synthetic concentric-ring pin pattern on a dome and its camera image.
#pragma once

#include <cmath>
#include <numbers>
#include <vector>

#include "sensors/camera.h"

namespace tactip {

/// Tips of a concentric-ring pattern (ring k: 6k pins, from +y towards +z) on an 18 mm
/// sphere, rings 0.15 rad (2.7 mm) apart: N = 127 for 6 rings, the outer ring ~219 px from
/// the image centre. Sensor frame, m, (N x 3) row-major; `shift_y_m` moves every tip along y.
inline std::vector<float> DomeTips(int rings, double shift_y_m = 0.0) {
  std::vector<float> pos_m;
  for (int r = 0; r <= rings; ++r) {
    const int n = r == 0 ? 1 : 6 * r;
    for (int k = 0; k < n; ++k) {
      const double azimuth = 2.0 * std::numbers::pi * k / n, polar = 0.15 * r;
      pos_m.push_back(static_cast<float>(0.018 * std::cos(polar)));
      pos_m.push_back(static_cast<float>(0.018 * std::sin(polar) * std::cos(azimuth) + shift_y_m));
      pos_m.push_back(static_cast<float>(0.018 * std::sin(polar) * std::sin(azimuth)));
    }
  }
  return pos_m;
}

/// The image positions (N x 2) of tips `pos_m` through `camera`.
inline std::vector<float> ProjectTips(const CameraConfig& camera, const std::vector<float>& pos_m) {
  std::vector<float> px;
  const PinholeCamera cam(camera);
  for (size_t i = 0; i + 2 < pos_m.size(); i += 3) {
    const auto uv = cam.Project({pos_m[i], pos_m[i + 1], pos_m[i + 2]});
    px.push_back(static_cast<float>(uv[0]));
    px.push_back(static_cast<float>(uv[1]));
  }
  return px;
}

}  // namespace tactip
