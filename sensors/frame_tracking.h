#pragma once
// The hardware pin pipeline on a folder of real camera frames (PNG): markers in every frame
// (sensors/frame_blobs.h, settings chosen from the first frame), pins numbered from the first
// frame's markers (NumberPins), tracked nearest-neighbour through the rest; what `tactip
// track` writes as a pin CSV.

#include <optional>
#include <string>
#include <vector>

#include "detectors/pin_frame.h"
#include "sensors/frame_blobs.h"

namespace tactip {

/// The PNG files (extension .png, any case) directly in folder `dir`, sorted by file name.
/// Throws InputError naming `option` and the folder if it is missing, not a folder or
/// holds no PNG.
std::vector<std::string> PngFramesIn(const std::string& dir, const std::string& option);

/// How to track: the frame rate and the settings that override the first frame's choice.
struct TrackSettings {
  double fps_hz = 100.0;               ///< frame k at k / fps_hz s
  std::optional<double> gate_px;       ///< tracking gate (default: chosen from the first frame)
  std::optional<double> min_area_px;   ///< smallest marker (default: chosen from the first frame)
};

/// A tracked recording: the pins per frame, the settings used and what each frame showed.
struct TrackedRecording {
  std::vector<PinFrame> frames;
  FrameBlobParams params;
  std::vector<int> found;  ///< per frame: pins given a marker within the gate
  std::vector<int> blobs;  ///< per frame: markers found
};

/// Tracks the pins through the frames `files` (greyscale or colour PNGs of one size). Throws
/// InputError naming the file if one cannot be read as an image, differs in size from the
/// first, or the first frame shows no marker. Reads every frame before returning.
TrackedRecording TrackPngFrames(const std::vector<std::string>& files, const TrackSettings& settings);

}  // namespace tactip
