#pragma once
// The hardware pin pipeline on a folder of real camera frames (PNG): blobs in every frame
// (SimpleBlobDetector), pins numbered from the first frame's blobs (NumberPins), tracked
// nearest-neighbour through the rest; what `tactip track` writes as a pin CSV.

#include <string>
#include <vector>

#include "detectors/pin_frame.h"
#include "sensors/tactile_image.h"

namespace tactip {

/// The PNG files (extension .png, any case) directly in folder `dir`, sorted by file name.
/// Throws InputError naming `option` and the folder if it is missing, not a folder or
/// holds no PNG.
std::vector<std::string> PngFramesIn(const std::string& dir, const std::string& option);

/// Tracks the pins through the frames `files` (greyscale or colour PNGs of one size),
/// frame k at time k / `fps_hz`, with the blob detector and gate of `cfg`. Throws
/// InputError naming the file if one cannot be read as an image, differs in size from the
/// first, or the first frame shows no blob. Reads every frame before returning.
std::vector<PinFrame> TrackPngFrames(const std::vector<std::string>& files, double fps_hz,
                                     const TactileImageConfig& cfg);

}  // namespace tactip
