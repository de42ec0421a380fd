#include "sensors/frame_blobs.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <opencv2/imgproc.hpp>

#include "sensors/blob_tracker.h"
#include "sim/base/errors.h"

namespace tactip {

namespace {

// A marker's component fills at least this share of its bounding box (a disc 0.79, two
// touching discs ~0.4) and is at most this elongated; rim arcs are neither.
constexpr double kMinFill = 0.3;
constexpr double kMaxAspect = 4.0;
// Components smaller than this are specks, whatever the markers' size.
constexpr double kSpeckAreaPx = 3.0;

struct Component {
  cv::Point2f centre;
  double area = 0.0;
};

// The marker-shaped components of `grey` at `p`'s threshold and polarity, of any area.
std::vector<Component> MarkerShaped(const cv::Mat& grey, const FrameBlobParams& p) {
  cv::Mat binary;
  cv::threshold(grey, binary, p.threshold, 255, p.inverted ? cv::THRESH_BINARY_INV : cv::THRESH_BINARY);
  cv::Mat labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(binary, labels, stats, centroids, 8, CV_32S);
  std::vector<Component> out;
  for (int k = 1; k < n; ++k) {
    const double area = stats.at<int>(k, cv::CC_STAT_AREA);
    const double w = stats.at<int>(k, cv::CC_STAT_WIDTH), h = stats.at<int>(k, cv::CC_STAT_HEIGHT);
    if (area < kSpeckAreaPx || area < kMinFill * w * h || std::max(w, h) > kMaxAspect * std::min(w, h)) continue;
    out.push_back({cv::Point2f(static_cast<float>(centroids.at<double>(k, 0)), static_cast<float>(centroids.at<double>(k, 1))),
                   area});
  }
  return out;
}

double Median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

}  // namespace

FrameBlobParams ChooseFrameBlobParams(const cv::Mat& grey, const char* file) {
  FrameBlobParams p;
  cv::Mat binary;
  p.threshold = cv::threshold(grey, binary, 0, 255, cv::THRESH_BINARY | cv::THRESH_OTSU);
  // Markers are the minority: most of a frame bright means dark markers on a bright skin.
  p.inverted = 2 * static_cast<size_t>(cv::countNonZero(binary)) > binary.total();
  const std::vector<Component> all = MarkerShaped(grey, p);
  if (all.empty()) {
    throw InputError(fmt::format("'{}' (the first frame) shows no marker-like blobs", file));
  }
  std::vector<double> areas;
  for (const Component& c : all) areas.push_back(c.area);
  p.median_area_px = Median(areas);
  p.min_area_px = std::max(kSpeckAreaPx, 0.1 * p.median_area_px);
  p.max_area_px = 6.0 * p.median_area_px;
  const std::vector<cv::Point2f> kept = FrameBlobs(grey, p);
  p.markers = static_cast<int>(kept.size());
  p.gate_px = 0.5 * MedianNearestDistance(kept);
  if (p.gate_px <= 0.0) p.gate_px = std::sqrt(p.median_area_px);
  return p;
}

std::vector<cv::Point2f> FrameBlobs(const cv::Mat& grey, const FrameBlobParams& p) {
  std::vector<cv::Point2f> out;
  for (const Component& c : MarkerShaped(grey, p)) {
    if (c.area >= p.min_area_px && c.area <= p.max_area_px) out.push_back(c.centre);
  }
  return out;
}

}  // namespace tactip
