#include "sensors/image_frames.h"

#include <zlib.h>

#include <string>

#include "sensors/hdf5_io.h"
#include "sim/base/errors.h"

namespace tactip {

CompressedFrame CompressFrame(const std::uint8_t* pixels, std::size_t bytes) {
  // One zlib stream at the level of every other chunked array (hdf5::kDeflateLevel).
  uLongf size = compressBound(static_cast<uLong>(bytes));
  CompressedFrame out(size);
  if (compress2(out.data(), &size, pixels, static_cast<uLong>(bytes), static_cast<int>(hdf5::kDeflateLevel)) != Z_OK) {
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
