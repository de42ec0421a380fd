#pragma once
// Markers in real TacTip frames, with settings chosen from the first frame: binarised or
// grey, white markers on a dark skin or inverted, blobs from a few px to ~100 px, a bright
// rim around the pattern. Each frame is thresholded at the first frame's Otsu level, its
// connected components are the candidate markers, and those of a marker's size and shape
// are kept (the rim, its arcs and noise specks are not).

#include <vector>

#include <opencv2/core.hpp>

namespace tactip {

/// Blob settings chosen from a first frame (docs/images-and-tracking.md#tracking-real-camera-frames).
struct FrameBlobParams {
  double threshold = 128.0;     ///< grey level between skin and marker (Otsu on the first frame)
  bool inverted = false;        ///< dark markers on a bright skin (most of the first frame above the threshold)
  double median_area_px = 0.0;  ///< the first frame's markers' median area
  double min_area_px = 0.0;     ///< smallest component kept: a tenth of the median (markers shrink when pressed)
  double max_area_px = 0.0;     ///< largest: 6 x the median (two or three merged markers; not the rim)
  double gate_px = 0.0;         ///< tracking gate: half the median nearest-neighbour distance
  int markers = 0;              ///< markers kept in the first frame
};

/// The settings of the first frame `grey` (CV_8UC1). Throws InputError naming `file` if no
/// marker-like component is found.
FrameBlobParams ChooseFrameBlobParams(const cv::Mat& grey, const char* file);

/// The centroids (px, pixel centres at whole numbers) of the components of `grey` of a
/// marker's size and shape under `p`.
std::vector<cv::Point2f> FrameBlobs(const cv::Mat& grey, const FrameBlobParams& p);

}  // namespace tactip
