#pragma once
// Rendered tactile images: what the TacTip's internal camera sees. Each pin tip is a bright
// disc on the dark skin, its radius the physical tip radius projected through the camera,
// its brightness falling off towards the rim; then optical blur and pixel noise, uint8.
// The `images` config section also holds the blob pipeline's settings (blob_tracker.h).

#include <array>
#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

#include "sensors/camera.h"
#include "sim/config.h"

namespace tactip {

/// Image rendering and blob tracking (the `images` section). Nothing is rendered unless
/// `enabled` (the lean-scene rule: a run pays only for what it records).
struct TactileImageConfig {
  bool enabled = false;              ///< render images and track blobs in every camera frame
  double pin_tip_radius_mm = 0.5;    ///< radius of a pin's white tip (marker), mm
  double skin_grey = 25.0;           ///< grey level of the black skin between the markers
  double pin_grey = 225.0;           ///< grey level of a marker on the camera axis
  double rim_falloff_power = 4.0;    ///< marker brightness above the skin scales as cos^p(ray angle)
  double blur_sigma_px = 1.0;        ///< optical blur: std of the Gaussian point-spread function, px
  double noise_grey = 2.0;           ///< std of Gaussian pixel noise, grey levels
  double threshold_min = 60.0;       ///< blob detector: first grey threshold
  double threshold_max = 190.0;      ///< blob detector: thresholds stop below this
  double threshold_step = 32.0;      ///< blob detector: step between thresholds
  double min_blob_area_px = 12.0;    ///< blob detector: smallest blob area, px^2
  double max_blob_area_px = 2500.0;  ///< blob detector: largest blob area, px^2
  double gate_px = 10.0;             ///< tracking: farthest a pin may move between frames, px

  template <class V>
  void Visit(V& v) {
    v("enabled", enabled, "",
      "Render the internal camera's image at every camera frame (sensor.width_px x sensor.height_px, uint8), run "
      "the blob pipeline on it and record images, pins/detected_px and pins/detected_valid (command line: "
      "generate --images).");
    v("pin_tip_radius_mm", pin_tip_radius_mm, "mm",
      "Radius of a pin's white tip; drawn with radius f * r / depth px (0.5 mm: ~6.5 px at the centre pin, the "
      "size of a real TacTip's markers relative to their spacing).",
      Bounds::Closed(0.05, 5.0));
    v("skin_grey", skin_grey, "grey", "Grey level of the black skin between the markers (0-255).",
      Bounds::Closed(0.0, 255.0));
    v("pin_grey", pin_grey, "grey",
      "Grey level of a marker on the camera axis (0-255); real frames show white markers on black.",
      Bounds::Closed(0.0, 255.0));
    v("rim_falloff_power", rim_falloff_power, "",
      "Marker brightness above the skin scales as cos^p of the angle between its ray and the camera axis: 4 is the "
      "cos^4 fall-off of a lens's natural vignetting (the dome's lighting also dims towards the rim).",
      Bounds::Closed(0.0, 20.0));
    v("blur_sigma_px", blur_sigma_px, "px",
      "Optical blur: std of the Gaussian point-spread function (0: none; ~1 px for a small board camera slightly "
      "out of focus on a curved surface).",
      Bounds::Closed(0.0, 20.0));
    v("noise_grey", noise_grey, "grey", "Std of Gaussian pixel noise added after the blur (sensor read noise).",
      Bounds::Closed(0.0, 100.0));
    v("threshold_min", threshold_min, "grey",
      "Blob detector (OpenCV SimpleBlobDetector): the first of the grey thresholds the image is cut at.",
      Bounds::Closed(1.0, 254.0));
    v("threshold_max", threshold_max, "grey", "Blob detector: thresholds run from threshold_min up to below this.",
      Bounds::Closed(2.0, 255.0));
    v("threshold_step", threshold_step, "grey",
      "Blob detector: step between thresholds; a blob must appear at two thresholds to count.",
      Bounds::Closed(1.0, 254.0));
    v("min_blob_area_px", min_blob_area_px, "px^2", "Blob detector: smallest blob area kept (drops noise specks).",
      Bounds::Closed(1.0, 1e6));
    v("max_blob_area_px", max_blob_area_px, "px^2", "Blob detector: largest blob area kept (drops merged blobs).",
      Bounds::Closed(1.0, 1e7));
    v("gate_px", gate_px, "px",
      "Tracking: a pin takes the nearest blob within this distance of its previous position, else keeps that "
      "position with detected_valid = 0; below half the pin spacing (~37 px in the default image).",
      Bounds::LeftOpen(0.0, 1000.0));
  }
  /// Thresholds that leave room for two levels (a blob must repeat), areas in order; throws
  /// InputError naming the key.
  void ValidateRules() const;
};

/// Image radius (px) of a pin tip of radius `pin_tip_radius_mm` at `depth_m` in front of
/// `camera`: f r / depth, f the mean of the two focal lengths.
double TipRadiusPx(const CameraConfig& camera, double pin_tip_radius_mm, double depth_m);

/// True when the whole tip disc of a pin at `p_sensor_m` (sensor frame, m), of radius
/// `pin_tip_radius_mm`, lies inside `camera`'s image: a tip cut by the border (or outside the
/// field of view, as the outer rings of a wide fingerprint pattern are) cannot be located.
bool TipInImage(const CameraConfig& camera, double pin_tip_radius_mm, const std::array<double, 3>& p_sensor_m);

/// Renders the internal camera's image of N pin tips. Not thread-safe; one per sensor.
class TactileImageRenderer {
 public:
  /// `noise_seed` seeds the pixel noise (OpenCV's cv::RNG, deterministic for a seed).
  TactileImageRenderer(const TactileImageConfig& cfg, const CameraConfig& camera, std::uint64_t noise_seed);

  /// The image (height_px x width_px, CV_8UC1) of pins at image positions `px` (N x 2,
  /// row-major, noise-free) whose tips lie at `pos_m` (N x 3, sensor frame, m). Throws
  /// std::invalid_argument if the sizes disagree. The returned image is reused by the next call.
  const cv::Mat& Render(const std::vector<float>& px, const std::vector<float>& pos_m);

  /// The last rendered image (empty before the first Render).
  const cv::Mat& image() const { return image_; }
 private:
  TactileImageConfig cfg_;
  CameraConfig camera_;
  cv::RNG rng_;
  cv::Mat drawn_, blurred_, noise_, image_;
};

}  // namespace tactip
