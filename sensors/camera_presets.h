#pragma once
// The `--camera NAME` presets: the sensor.* keys (and the external camera's principal point,
// which shares the image) of the real cameras the simulated one can
// stand in for (docs/model.md#the-camera).
//   tactip-640x480    the 127-pin TacTip's 640x480 camera of the real frames the press and
//                     noise figures were measured on (outer ring R = 131 px); the default.
//   pose-dataset-256  the 256x256 crops of the public TacTip pose and shear datasets
//                     (R = 84.4 px); the pixel noise sizes scaled by 84.4 / 131.
//   legacy            the camera and noise before the real-camera calibration (f = 580 px,
//                     R = 202 px; independent noise 0.28 px), to reproduce older datasets.

#include <string>
#include <vector>

namespace tactip {

/// The names of the presets, default first.
const std::vector<std::string>& CameraPresetNames();

/// The "sensor.key=value" overrides of preset `name` (throws InputError for another name).
std::vector<std::string> CameraPreset(const std::string& name);

}  // namespace tactip
