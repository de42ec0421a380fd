#pragma once
// One simulated sensor's camera as hardware runs it: render the frame (tactile_image.h),
// find the blobs and track the pins (blob_tracker.h), keep the frame compressed.

#include <cstdint>
#include <optional>
#include <vector>

#include "sensors/blob_tracker.h"
#include "sensors/image_frames.h"
#include "sensors/tactile_image.h"

namespace tactip {

/// What the image pipeline produced at one camera frame.
struct ImageReading {
  CompressedFrame image;                     ///< the rendered frame (H x W uint8), zlib-compressed
  std::vector<float> detected_px;            ///< (N,2) tracked pin positions, px
  std::vector<std::uint8_t> detected_valid;  ///< (N) 1 = a blob within the gate this frame
};

/// Renders, detects and tracks the frames of one sensor. Not thread-safe; one per sensor.
class SensorImagePipeline {
 public:
  /// `noise_seed` seeds the pixel noise.
  SensorImagePipeline(const TactileImageConfig& cfg, const CameraConfig& camera, std::uint64_t noise_seed);

  /// One frame of pins at noise-free image positions `clean_px` (N x 2) with tips at `pos_m`
  /// (N x 3, sensor frame, m). The first frame starts the tracker at `clean_px` (the
  /// projected positions), as hardware starts at the rest frame's blobs.
  const ImageReading& Capture(const std::vector<float>& clean_px, const std::vector<float>& pos_m);
  /// The last rendered frame (CV_8UC1).
  const cv::Mat& image() const { return renderer_.image(); }

 private:
  TactileImageRenderer renderer_;
  BlobDetector detector_;
  double gate_px_;
  std::optional<PinTracker> tracker_;
  ImageReading reading_;
};

}  // namespace tactip
