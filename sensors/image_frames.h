#pragma once
// Recorded camera frames held compressed: each frame one zlib (deflate) stream, exactly the
// bytes an HDF5 chunk of one frame holds under the deflate filter, so a run's images are
// buffered, written and read without ever being held uncompressed all at once.

#include <cstdint>
#include <vector>

namespace tactip {

/// One frame's pixels, zlib-compressed (what HDF5's deflate filter stores).
using CompressedFrame = std::vector<std::uint8_t>;

/// Compresses `bytes` pixels at `pixels` with zlib (level 1, Z_BEST_SPEED).
CompressedFrame CompressFrame(const std::uint8_t* pixels, std::size_t bytes);

/// The `bytes` pixels of `frame`; throws InputError if it is not a zlib stream of that size.
std::vector<std::uint8_t> DecompressFrame(const CompressedFrame& frame, std::size_t bytes);

}  // namespace tactip
