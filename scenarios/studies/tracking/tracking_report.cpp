#include "scenarios/studies/tracking/tracking_report.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "sensors/tactile_image.h"
#include "sim/base/errors.h"

namespace tactip {

namespace {

constexpr double kWithinPx = 1.0;  // the acceptance radius

/// Distance (px) of image point (u, v) from the projection of tip sample `k` (frame * N + pin).
double ErrorPx(const PinholeCamera& camera, const std::vector<float>& pos_m, size_t k, float u, float v) {
  const auto truth = camera.Project({pos_m[3 * k], pos_m[3 * k + 1], pos_m[3 * k + 2]});
  return std::hypot(u - truth[0], v - truth[1]);
}

}  // namespace

double TrackingFigures::WithinFraction() const {
  return samples > 0 ? static_cast<double>(within_1px) / static_cast<double>(samples)
                     : std::numeric_limits<double>::quiet_NaN();
}

double TrackingFigures::RmsPx() const {
  return samples > 0 ? std::sqrt(sum_sq_px2 / static_cast<double>(samples)) : std::numeric_limits<double>::quiet_NaN();
}

void TrackingFigures::Add(const TrackingFigures& o) {
  samples += o.samples;
  out_of_view += o.out_of_view;
  within_1px += o.within_1px;
  misses += o.misses;
  sum_sq_px2 += o.sum_sq_px2;
  max_px = std::max(max_px, o.max_px);
  camera_within_1px += o.camera_within_1px;
}

TrackingFigures AnalyzeTracking(const SensorRecord& s, int run_index, const CameraConfig& camera_cfg,
                                double pin_tip_radius_mm, const std::string& path) {
  if (s.detected_px.empty()) {
    throw InputError(fmt::format("dataset '{}': {}/sensors/{} has no pins/detected_px (generate it with --images)",
                                 path, RunGroupName(run_index), s.name));
  }
  // Every (frame, pin): the tracked and the camera model's positions against the truth.
  const PinholeCamera camera(camera_cfg);
  TrackingFigures f;
  f.sensor = s.name;
  f.run = run_index;
  for (size_t k = 0; k < s.detected_valid.size(); ++k) {
    if (!TipInImage(camera_cfg, pin_tip_radius_mm, {s.pos_m[3 * k], s.pos_m[3 * k + 1], s.pos_m[3 * k + 2]})) {
      ++f.out_of_view;
      continue;
    }
    const double e = ErrorPx(camera, s.pos_m, k, s.detected_px[2 * k], s.detected_px[2 * k + 1]);
    const double e_camera = ErrorPx(camera, s.pos_m, k, s.pos_px[2 * k], s.pos_px[2 * k + 1]);
    f.within_1px += e < kWithinPx ? 1 : 0;
    f.camera_within_1px += e_camera < kWithinPx ? 1 : 0;
    f.misses += s.detected_valid[k] ? 0 : 1;
    f.sum_sq_px2 += e * e;
    f.max_px = std::max(f.max_px, e);
    ++f.samples;
  }
  return f;
}

std::string FormatTrackingReport(const std::vector<TrackingFigures>& rows, const std::vector<TrackingFigures>& totals) {
  std::string out = fmt::format("{:<12} {:>5} {:>10} {:>11} {:>10} {:>8} {:>8} {:>8} {:>11}\n", "sensor", "run",
                                "samples", "out_of_view", "within_1px", "rms_px", "max_px", "misses", "camera_1px");
  auto row = [&](const TrackingFigures& f, const std::string& run) {
    out += fmt::format("{:<12} {:>5} {:>10} {:>11} {:>10.4f} {:>8.3f} {:>8.2f} {:>8} {:>11.4f}\n", f.sensor, run,
                       f.samples, f.out_of_view, f.WithinFraction(), f.RmsPx(), f.max_px, f.misses,
                       f.samples > 0 ? static_cast<double>(f.camera_within_1px) / static_cast<double>(f.samples)
                                     : std::numeric_limits<double>::quiet_NaN());
  };
  for (const TrackingFigures& f : rows) row(f, std::to_string(f.run));
  for (const TrackingFigures& f : totals) row(f, "all");
  out += "samples: (frame, pin) pairs whose whole tip lies in the image (out_of_view: the others, not scored); "
         "within_1px: share of samples whose pins/detected_px lies within 1 px of the projection of pins/pos_m; "
         "misses: samples with detected_valid = 0; camera_1px: within_1px of the camera model's pins/pos_px\n";
  return out;
}

}  // namespace tactip
