#pragma once
// The `images` array of a sensor group in HDF5: (T, H, W) uint8, one deflate-compressed
// chunk per frame, written and read chunk by chunk as the compressed bytes the record
// holds (H5Dwrite_chunk / H5Dread_chunk). Internal to sensors/.

#include <hdf5.h>

#include <string>
#include <vector>

#include "sensors/hdf5_io.h"
#include "sensors/image_frames.h"

namespace tactip {

/// Writes `frames` (each a zlib stream of width x height pixels) as array `name` under
/// `parent` (path `where`): shape (T, height, width), chunk (1, height, width), deflate.
void WriteImageArray(hid_t parent, const char* name, const std::vector<CompressedFrame>& frames, int width, int height,
                     const std::string& where, hdf5::WriteErrors& err);

/// A frame stack read back: its frames (compressed) and size.
struct ImageStack {
  std::vector<CompressedFrame> frames;  ///< T frames, zlib
  int width = 0, height = 0;            ///< px
};

/// Reads image array `dset` (path `where`) of `frames` frames. Throws InputError (`source`
/// first) if it is not (T, H, W) uint8 chunked one frame per chunk under deflate alone, or a
/// frame is missing.
ImageStack ReadImageArray(hid_t dset, hsize_t frames, const std::string& source, const std::string& where);

}  // namespace tactip
