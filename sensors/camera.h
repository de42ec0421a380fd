#pragma once
// The internal camera of the TacTip: pinhole projection of the inner pin ends into the
// image, frame timing independent of the physics step, and the settings of the tracker's
// noise and missed detections (applied by sensors/pin_noise.h).

#include <array>
#include <string>

#include "sim/config.h"

namespace tactip {

/// Camera intrinsics, placement, rate and noise (the `sensor.` section).
struct CameraConfig {
  /// Allowed focal length per pixel of image size: a pinhole field of view of 157 to 2.9 degrees.
  static constexpr double kMinFocalPerPx = 0.1;
  static constexpr double kMaxFocalPerPx = 20.0;
  double frame_rate_hz = 100.0;   ///< frames per second
  int width_px = 640;             ///< image width
  int height_px = 480;            ///< image height
  double fx_px = 377.0;           ///< focal length in pixels, horizontal (outer ring at 131 px)
  double fy_px = 377.0;           ///< focal length in pixels, vertical
  double cx_px = 320.0;           ///< principal point, horizontal
  double cy_px = 240.0;           ///< principal point, vertical
  double camera_offset_mm = 25.0; ///< camera distance behind the dome centre, on the axis
  std::string noise_model = "structured";  ///< independent or structured (sensors/pin_noise.h)
  double pixel_noise_px = 0.139;  ///< std of the independent Gaussian noise on each pixel coordinate
  double common_shift_px = 0.19;      ///< structured: std of the pattern's translation, per coordinate
  double common_rotation_deg = 0.089;  ///< structured: std of the pattern's rotation
  double common_scale_pct = 0.15;     ///< structured: std of the pattern's scale change
  double common_time_s = 0.012;       ///< structured: correlation time of the common mode
  double local_noise_px = 0.113;      ///< structured: std of the neighbour-correlated field, per coordinate
  double local_length_pitch = 1.2;    ///< structured: its kernel's std, in pattern pitches
  double dropout_prob = 0.005;    ///< probability that a pin is not detected in a frame

  template <class V>
  void Visit(V& v) {
    v("frame_rate_hz", frame_rate_hz, "Hz",
      "Camera frame rate; frames sample the physics state independently of the timestep.",
      Bounds::Closed(1.0, 2000.0));
    v("width_px", width_px, "px", "Image width.", Bounds::Closed(16, 8192));
    v("height_px", height_px, "px", "Image height.", Bounds::Closed(16, 8192));
    v("fx_px", fx_px, "px",
      "Horizontal focal length. 377 px puts the outer ring 131 px from the centre, as on the real 127-pin TacTip's "
      "640x480 camera (a ~2.1 mm lens on a 1/4-inch sensor, 81 degrees across; docs/model.md#the-camera); 0.1 to 20 "
      "x width_px (a field of view of 157 to 2.9 degrees).",
      Bounds::Closed(kMinFocalPerPx * 16, kMaxFocalPerPx * 8192));
    v("fy_px", fy_px, "px", "Vertical focal length; 0.1 to 20 x height_px.",
      Bounds::Closed(kMinFocalPerPx * 16, kMaxFocalPerPx * 8192));
    v("cx_px", cx_px, "px", "Principal point, horizontal; inside the image (0 to width_px).", Bounds::Closed(0, 8192));
    v("cy_px", cy_px, "px", "Principal point, vertical; inside the image (0 to height_px).", Bounds::Closed(0, 8192));
    v("camera_offset_mm", camera_offset_mm, "mm",
      "Distance of the camera's optical centre behind the dome centre along the sensor axis.",
      Bounds::Closed(1.0, 200.0));
    v("noise_model", noise_model, "",
      "Tracker noise on the pin positions. independent: Gaussian per pin and coordinate (pixel_noise_px), white "
      "in time. structured: a real TacTip's structure (docs/model.md#pin-noise): the whole pattern's translation, "
      "rotation and scale (common_*), slowly varying, plus a field correlated between neighbours (local_*), plus "
      "the independent part (pixel_noise_px).",
      Choices{"independent", "structured"});
    v("pixel_noise_px", pixel_noise_px, "px",
      "Std of the independent Gaussian noise per pixel coordinate. With the structured model's defaults, 0.139 px "
      "gives the hardware's 0.5 px/frame pin-speed noise; alone (independent model) 0.28 px does (|difference of two "
      "noisy 2-D positions| has mean 1.77 sigma; the legacy camera preset).",
      Bounds::Closed(0.0, 20.0));
    VisitStructured(v);
    v("dropout_prob", dropout_prob, "",
      "Probability that a pin is missed in a frame; a missed pin keeps its previous position and valid = 0.",
      Bounds::RightOpen(0.0, 1.0));
  }
  /// The structured noise model's keys.
  template <class V>
  void VisitStructured(V& v) {
    v("common_shift_px", common_shift_px, "px",
      "Structured noise: std of the whole pattern's translation per coordinate, the same for every pin.",
      Bounds::Closed(0.0, 20.0));
    v("common_rotation_deg", common_rotation_deg, "deg",
      "Structured noise: std of the whole pattern's rotation about the principal point.", Bounds::Closed(0.0, 10.0));
    v("common_scale_pct", common_scale_pct, "%",
      "Structured noise: std of the whole pattern's scale change about the principal point.",
      Bounds::Closed(0.0, 10.0));
    v("common_time_s", common_time_s, "s",
      "Structured noise: correlation time of the common translation, rotation and scale (first-order "
      "autoregressive; 0: white in time).",
      Bounds::Closed(0.0, 100.0));
    v("local_noise_px", local_noise_px, "px",
      "Structured noise: std per coordinate of the per-pin field correlated between neighbours (white in time).",
      Bounds::Closed(0.0, 20.0));
    v("local_length_pitch", local_length_pitch, "",
      "Structured noise: std of the neighbour field's Gaussian kernel in pattern pitches (mean nearest-neighbour "
      "distance in the first frame); neighbours d apart correlate by about exp(-d^2 / (4 l^2)). 0: independent.",
      Bounds::Closed(0.0, 20.0));
  }
  /// Focal lengths and principal point consistent with the image size.
  void ValidateRules() const;
};

/// Pinhole camera on the sensor axis looking along +x (the dome's outward axis).
/// Image u grows with sensor +y, image v grows with sensor -z (down).
class PinholeCamera {
 public:
  explicit PinholeCamera(const CameraConfig& cfg) : cfg_(cfg) {}
  /// Projects a point in the sensor frame (metres) to pixels; the point must lie in
  /// front of the camera.
  std::array<double, 2> Project(const std::array<double, 3>& p_sensor_m) const;
  /// Largest image motion (px) per metre of motion of a point (sensor frame): the Frobenius
  /// norm of the projection's Jacobian at the point, which bounds every direction's gain.
  double ImageGain(const std::array<double, 3>& p_sensor_m) const;

 private:
  CameraConfig cfg_;
};

/// The external camera of the transparent rig (the `external.` section): it looks at the
/// outside of the skin through the clear plate, on the sensor axis in front of the apex,
/// facing the sensor. It moves with the sensor (fixed to the arm's mount) and shares the
/// internal camera's frame times.
struct ExternalCameraConfig {
  bool enabled = false;            ///< record external markers (transparent stimulus only)
  double distance_mm = 60.0;       ///< optical centre in front of the dome apex, along the axis
  double f_px = 580.0;             ///< focal length in pixels
  double cx_px = 320.0;            ///< principal point, horizontal
  double cy_px = 240.0;            ///< principal point, vertical
  double pixel_noise_px = 0.28;    ///< std of Gaussian noise per pixel coordinate

  template <class V>
  void Visit(V& v) {
    v("enabled", enabled, "",
      "Record the outer contact points (external markers) in a second camera, as external/pos_px. Needs a "
      "transparent stimulus (rail.stimulus = acrylic).");
    v("distance_mm", distance_mm, "mm",
      "Distance of the external camera's optical centre in front of the dome apex, on the sensor axis, looking "
      "back at the skin (its image is mirrored relative to the internal camera's).",
      Bounds::Closed(5.0, 1000.0));
    v("f_px", f_px, "px",
      "Focal length of the external camera in pixels; its image has the internal camera's size (sensor.width_px x "
      "sensor.height_px), so 0.1 to 20 x sensor.width_px.",
      Bounds::Closed(CameraConfig::kMinFocalPerPx * 16, CameraConfig::kMaxFocalPerPx * 8192));
    v("cx_px", cx_px, "px", "Principal point, horizontal; inside the image (0 to sensor.width_px).",
      Bounds::Closed(0, 8192));
    v("cy_px", cy_px, "px", "Principal point, vertical; inside the image (0 to sensor.height_px).",
      Bounds::Closed(0, 8192));
    v("pixel_noise_px", pixel_noise_px, "px", "Std of Gaussian noise per pixel coordinate of an external marker.",
      Bounds::Closed(0.0, 20.0));
  }
  void ValidateRules() const {}
  /// Focal length and principal point consistent with the image size of `image` (the
  /// internal camera's, which the external camera shares).
  void ValidateIntrinsics(const CameraConfig& image) const;
};

/// Pinhole projection of the external camera: at sensor x = apex + distance, looking
/// along -x. Image u grows with sensor -y (the mirror of the internal view), v with -z.
class ExternalCamera {
 public:
  ExternalCamera(const ExternalCameraConfig& cfg, double apex_x_m) : cfg_(cfg), cam_x_(apex_x_m + cfg.distance_mm * 1e-3) {}
  std::array<double, 2> Project(const std::array<double, 3>& p_sensor_m) const;

 private:
  ExternalCameraConfig cfg_;
  double cam_x_;
};

/// Frame `k` of a camera at `rate_hz` is taken at the physics step nearest to k / rate.
long long FrameStep(long long k, double rate_hz, double timestep_s);

}  // namespace tactip
