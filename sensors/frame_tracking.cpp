#include "sensors/frame_tracking.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <optional>

#include <fmt/format.h>
#include <opencv2/imgcodecs.hpp>

#include "sensors/blob_tracker.h"
#include "sim/base/errors.h"

namespace tactip {

namespace {

/// True when `path` ends in ".png", any case.
bool IsPng(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext == ".png";
}

/// Frame `file` as 8-bit greyscale; throws InputError if it cannot be read as an image.
cv::Mat ReadGreyFrame(const std::string& file) {
  cv::Mat grey;
  try {
    grey = cv::imread(file, cv::IMREAD_GRAYSCALE);
  } catch (const cv::Exception&) {
    grey.release();  // a decoder error is reported as an unreadable file
  }
  if (grey.empty()) throw InputError(fmt::format("'{}' cannot be read as a PNG image", file));
  return grey;
}

/// A PinFrame of the tracker's pins at `time_s`.
PinFrame FrameOf(const PinTracker& tracker, double time_s) {
  PinFrame f;
  f.time_s = time_s;
  f.pos_px.resize(tracker.size(), 2);
  for (int i = 0; i < tracker.size(); ++i) {
    f.pos_px(i, 0) = tracker.positions()[static_cast<size_t>(i)].x;
    f.pos_px(i, 1) = tracker.positions()[static_cast<size_t>(i)].y;
  }
  f.valid.assign(tracker.valid().begin(), tracker.valid().end());
  return f;
}

}  // namespace

std::vector<std::string> PngFramesIn(const std::string& dir, const std::string& option) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw InputError(fmt::format("{} '{}': no such folder", option, dir));
  std::vector<std::string> files;
  for (const fs::directory_entry& e : fs::directory_iterator(dir, ec)) {
    if (e.is_regular_file(ec) && IsPng(e.path())) files.push_back(e.path().string());
  }
  if (ec) throw InputError(fmt::format("{} '{}': cannot list the folder ({})", option, dir, ec.message()));
  if (files.empty()) throw InputError(fmt::format("{} '{}': the folder holds no PNG frames (*.png)", option, dir));
  // By file name, so frame_0009.png comes before frame_0010.png.
  std::sort(files.begin(), files.end(), [](const std::string& a, const std::string& b) {
    return fs::path(a).filename().string() < fs::path(b).filename().string();
  });
  return files;
}

TrackedRecording TrackPngFrames(const std::vector<std::string>& files, const TrackSettings& settings) {
  TrackedRecording out;
  cv::Size size;
  std::optional<PinTracker> tracker;
  for (size_t k = 0; k < files.size(); ++k) {
    const cv::Mat grey = ReadGreyFrame(files[k]);
    // Every frame the first frame's size; the settings from the first frame.
    if (k == 0) {
      size = grey.size();
      out.params = ChooseFrameBlobParams(grey, files[k].c_str());
      if (settings.min_area_px) out.params.min_area_px = *settings.min_area_px;
      if (settings.gate_px) out.params.gate_px = *settings.gate_px;
    }
    if (grey.size() != size) {
      throw InputError(fmt::format("'{}' is {} x {} px, but the first frame '{}' is {} x {} px", files[k], grey.cols,
                                   grey.rows, files[0], size.width, size.height));
    }
    const std::vector<cv::Point2f> blobs = FrameBlobs(grey, out.params);
    // The pins: the first frame's markers in the documented order, then tracked.
    if (!tracker) {
      if (blobs.empty()) {
        throw InputError(fmt::format("'{}' (the first frame) shows no markers of at least {} px", files[k],
                                     out.params.min_area_px));
      }
      tracker.emplace(NumberPins(blobs), out.params.gate_px);
    }
    tracker->Update(blobs);
    out.frames.push_back(FrameOf(*tracker, static_cast<double>(k) / settings.fps_hz));
    out.found.push_back(static_cast<int>(std::count(tracker->valid().begin(), tracker->valid().end(), 1)));
    out.blobs.push_back(static_cast<int>(blobs.size()));
  }
  return out;
}

}  // namespace tactip
