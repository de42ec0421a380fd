#include "sensors/image_frames.h"

#include <zlib.h>

#include <stdexcept>
#include <string>

#include "sim/base/errors.h"

namespace tactip {

CompressedFrame CompressFrame(const std::uint8_t* pixels, std::size_t bytes) {
  // One zlib stream at the fastest level: a noisy frame compresses to ~48 % at level 1 and
  // ~46 % at level 4, which takes twice as long (measured on default 640 x 480 frames).
  uLongf size = compressBound(static_cast<uLong>(bytes));
  CompressedFrame out(size);
  if (compress2(out.data(), &size, pixels, static_cast<uLong>(bytes), Z_BEST_SPEED) != Z_OK) {
    throw std::runtime_error("zlib could not compress a frame of " + std::to_string(bytes) + " bytes");
  }
  out.resize(size);
  return out;
}

std::vector<std::uint8_t> DecompressFrame(const CompressedFrame& frame, std::size_t bytes) {
  std::vector<std::uint8_t> out(bytes);
  uLongf size = static_cast<uLongf>(bytes);
  const int status = uncompress(out.data(), &size, frame.data(), static_cast<uLong>(frame.size()));
  if (status != Z_OK || size != bytes) {
    throw InputError("an image frame is not a zlib stream of " + std::to_string(bytes) + " pixels");
  }
  return out;
}

}  // namespace tactip
