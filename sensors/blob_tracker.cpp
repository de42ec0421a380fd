#include "sensors/blob_tracker.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

namespace tactip {

namespace {

/// Azimuths this little below 0 (rounding in the centroid) count as 0, not as nearly 2 pi.
constexpr double kAzimuthSlackRad = 1e-3;

/// Squared distance between two image points (px^2).
double Dist2(const cv::Point2f& a, const cv::Point2f& b) {
  const double du = a.x - b.x, dv = a.y - b.y;
  return du * du + dv * dv;
}

}  // namespace

double MedianNearestDistance(const std::vector<cv::Point2f>& blobs) {
  if (blobs.size() < 2) return 0.0;
  std::vector<double> nearest;
  for (size_t i = 0; i < blobs.size(); ++i) {
    double best = std::numeric_limits<double>::infinity();
    for (size_t j = 0; j < blobs.size(); ++j) {
      if (j != i) best = std::min(best, Dist2(blobs[i], blobs[j]));
    }
    nearest.push_back(std::sqrt(best));
  }
  std::nth_element(nearest.begin(), nearest.begin() + static_cast<long>(nearest.size() / 2), nearest.end());
  return nearest[nearest.size() / 2];
}

BlobDetector::BlobDetector(const TactileImageConfig& cfg) {
  // Bright blobs over a range of thresholds; a blob must repeat at two of them.
  cv::SimpleBlobDetector::Params p;
  p.minThreshold = static_cast<float>(cfg.threshold_min);
  p.maxThreshold = static_cast<float>(cfg.threshold_max);
  p.thresholdStep = static_cast<float>(cfg.threshold_step);
  p.minRepeatability = 2;
  p.minDistBetweenBlobs = 2.0f;
  p.filterByColor = true;
  p.blobColor = 255;
  p.filterByArea = true;
  p.minArea = static_cast<float>(cfg.min_blob_area_px);
  p.maxArea = static_cast<float>(cfg.max_blob_area_px);
  // Shape filters off: markers near the rim are seen obliquely.
  p.filterByCircularity = false;
  p.filterByConvexity = false;
  p.filterByInertia = false;
  detector_ = cv::SimpleBlobDetector::create(p);
}

std::vector<cv::Point2f> BlobDetector::Detect(const cv::Mat& grey) const {
  std::vector<cv::KeyPoint> keys;
  detector_->detect(grey, keys);
  std::vector<cv::Point2f> out;
  out.reserve(keys.size());
  for (const cv::KeyPoint& k : keys) out.push_back(k.pt);
  return out;
}

PinTracker::PinTracker(std::vector<cv::Point2f> start, double gate_px)
    : pos_(std::move(start)), valid_(pos_.size(), 1), gate_px_(gate_px) {}

void PinTracker::Update(const std::vector<cv::Point2f>& blobs) {
  // Each pin independently: the nearest blob to its previous position, if within the gate.
  const double gate2 = gate_px_ * gate_px_;
  for (size_t i = 0; i < pos_.size(); ++i) {
    double best = std::numeric_limits<double>::infinity();
    size_t best_j = 0;
    for (size_t j = 0; j < blobs.size(); ++j) {
      const double d2 = Dist2(pos_[i], blobs[j]);
      if (d2 < best) {
        best = d2;
        best_j = j;
      }
    }
    valid_[i] = best <= gate2 ? 1 : 0;
    if (valid_[i]) pos_[i] = blobs[best_j];
  }
}

std::vector<cv::Point2f> NumberPins(const std::vector<cv::Point2f>& blobs) {
  if (blobs.empty()) return {};
  // Polar coordinates about the blobs' centroid: radius, and azimuth from +u towards -v.
  cv::Point2f c(0.0f, 0.0f);
  for (const cv::Point2f& b : blobs) c += b;
  c *= 1.0f / static_cast<float>(blobs.size());
  struct Polar {
    double radius, azimuth;
    cv::Point2f at;
  };
  std::vector<Polar> polar;
  for (const cv::Point2f& b : blobs) {
    double az = std::atan2(-(b.y - c.y), b.x - c.x);
    if (az < -kAzimuthSlackRad) az += 2.0 * std::numbers::pi;
    polar.push_back({std::hypot(b.x - c.x, b.y - c.y), az, b});
  }
  std::sort(polar.begin(), polar.end(), [](const Polar& a, const Polar& b) { return a.radius < b.radius; });
  // Rings: split where the radius jumps by more than half the typical pin spacing; then
  // each ring by azimuth.
  const double ring_gap = 0.5 * MedianNearestDistance(blobs);
  std::vector<cv::Point2f> out;
  size_t begin = 0;
  for (size_t k = 1; k <= polar.size(); ++k) {
    if (k < polar.size() && polar[k].radius - polar[k - 1].radius <= ring_gap) continue;
    std::sort(polar.begin() + static_cast<long>(begin), polar.begin() + static_cast<long>(k),
              [](const Polar& a, const Polar& b) { return a.azimuth < b.azimuth; });
    for (size_t j = begin; j < k; ++j) out.push_back(polar[j].at);
    begin = k;
  }
  return out;
}

}  // namespace tactip
