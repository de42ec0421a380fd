#include "sensors/camera_presets.h"

#include <fmt/format.h>

#include "sensors/camera.h"
#include "sim/config.h"

namespace tactip {

namespace {

// The pattern radius of the public pose datasets' crops over the 640x480 camera's
// (real-sensor sections 5 and 1).
constexpr double kPoseDatasetRadiusPx = 84.4;
constexpr double kTacTipRadiusPx = 131.0;

// The defaults' focal length and noise scaled by `s`, in a `size` x `size` image centred on
// the pattern (the external camera's principal point too: it shares the image size).
std::vector<std::string> ScaledSquare(int size, double s) {
  const CameraConfig d;
  return {fmt::format("sensor.width_px={}", size),
          fmt::format("sensor.height_px={}", size),
          fmt::format("sensor.fx_px={:.6g}", d.fx_px * s),
          fmt::format("sensor.fy_px={:.6g}", d.fy_px * s),
          fmt::format("sensor.cx_px={:.6g}", 0.5 * size),
          fmt::format("sensor.cy_px={:.6g}", 0.5 * size),
          fmt::format("external.cx_px={:.6g}", 0.5 * size),  // the external camera shares the image size
          fmt::format("external.cy_px={:.6g}", 0.5 * size),
          "sensor.noise_model=" + d.noise_model,
          fmt::format("sensor.pixel_noise_px={:.4g}", d.pixel_noise_px * s),
          fmt::format("sensor.common_shift_px={:.4g}", d.common_shift_px * s),
          fmt::format("sensor.local_noise_px={:.4g}", d.local_noise_px * s)};
}

}  // namespace

const std::vector<std::string>& CameraPresetNames() {
  static const std::vector<std::string> names = {"tactip-640x480", "pose-dataset-256", "legacy"};
  return names;
}

std::vector<std::string> CameraPreset(const std::string& name) {
  const CameraConfig d;
  if (name == "tactip-640x480") {
    return {"sensor.width_px=640",
            "sensor.height_px=480",
            fmt::format("sensor.fx_px={}", d.fx_px),
            fmt::format("sensor.fy_px={}", d.fy_px),
            "sensor.cx_px=320",
            "sensor.cy_px=240",
            "external.cx_px=320",
            "external.cy_px=240",
            "sensor.noise_model=" + d.noise_model,
            fmt::format("sensor.pixel_noise_px={}", d.pixel_noise_px),
            fmt::format("sensor.common_shift_px={}", d.common_shift_px),
            fmt::format("sensor.local_noise_px={}", d.local_noise_px)};
  }
  if (name == "pose-dataset-256") return ScaledSquare(256, kPoseDatasetRadiusPx / kTacTipRadiusPx);
  if (name == "legacy") {
    return {"sensor.width_px=640", "sensor.height_px=480", "sensor.fx_px=580", "sensor.fy_px=580",
            "sensor.cx_px=320",    "sensor.cy_px=240",     "external.cx_px=320",
            "external.cy_px=240",  "sensor.noise_model=independent",
            "sensor.pixel_noise_px=0.28"};
  }
  throw InputError("--camera '" + config_detail::Escaped(name) +
                   "': unknown camera (known: tactip-640x480, pose-dataset-256, legacy)");
}

}  // namespace tactip
