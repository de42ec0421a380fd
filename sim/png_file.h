#pragma once
// PNG files of rendered images (through OpenCV's image codecs).

#include <string>

#include "sim/render_types.h"

namespace tactip {

/// Writes `image` to `path` as PNG, atomically (no half-written file on failure); throws
/// InputError naming the path when it cannot be written or the image is empty.
void SavePng(const RgbImage& image, const std::string& path);

/// Reads an image file (PNG) as RGB; throws InputError naming the path when it is missing or
/// not an image.
RgbImage ReadPng(const std::string& path);

}  // namespace tactip
