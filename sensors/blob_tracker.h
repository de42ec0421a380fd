#pragma once
// The pin pipeline of TacTip hardware: OpenCV's SimpleBlobDetector finds the bright markers
// in a camera frame; nearest-neighbour tracking gives each pin the blob nearest its previous
// position (within a gate), keeping that position with valid = 0 on a miss.

#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/features2d.hpp>

#include "sensors/tactile_image.h"

namespace tactip {

/// Finds bright blobs (markers) in greyscale frames with cv::SimpleBlobDetector, set up from
/// the `images` section (thresholds, areas; colour, circularity, convexity and inertia
/// filters off: a marker seen at an angle is an ellipse).
class BlobDetector {
 public:
  explicit BlobDetector(const TactileImageConfig& cfg);
  /// Blob centres (px, u right, v down; pixel centres at whole numbers) in `grey` (CV_8UC1).
  std::vector<cv::Point2f> Detect(const cv::Mat& grey) const;

 private:
  cv::Ptr<cv::SimpleBlobDetector> detector_;  // OpenCV's own handle type
};

/// Nearest-neighbour pin tracking. Not thread-safe.
class PinTracker {
 public:
  /// Pins start at `start` (px); a pin takes a blob at most `gate_px` from its previous position.
  PinTracker(std::vector<cv::Point2f> start, double gate_px);
  /// One frame's blobs: each pin takes the blob nearest its previous position if within the
  /// gate (valid 1), else keeps that position (valid 0).
  void Update(const std::vector<cv::Point2f>& blobs);

  /// Number of pins N.
  int size() const { return static_cast<int>(pos_.size()); }
  /// Each pin's position after the last frame (px).
  const std::vector<cv::Point2f>& positions() const { return pos_; }
  /// Each pin's detection in the last frame (1 = a blob within the gate).
  const std::vector<std::uint8_t>& valid() const { return valid_; }

 private:
  std::vector<cv::Point2f> pos_;
  std::vector<std::uint8_t> valid_;
  double gate_px_;
};

/// Median over the blobs of the distance to the nearest other blob (px); 0 for < 2 blobs.
double MedianNearestDistance(const std::vector<cv::Point2f>& blobs);

/// The blobs of a first real frame in the documented pin order: rings outwards from the
/// blobs' centroid (a new ring where the radius jumps by more than half the median
/// nearest-neighbour distance), each ring by azimuth from image +u towards image -v
/// (sensor +y towards +z), starting at 0 rad (-0.001 rad counts as 0). For a concentric-ring pattern seen straight on
/// this is the simulator's pin order (centre pin first).
std::vector<cv::Point2f> NumberPins(const std::vector<cv::Point2f>& blobs);

}  // namespace tactip
