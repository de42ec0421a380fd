#include "sensors/image_hdf5.h"

#include <limits>

#include "sim/base/errors.h"

namespace tactip {

using namespace hdf5;

void WriteImageArray(hid_t parent, const char* name, const std::vector<CompressedFrame>& frames, int width, int height,
                     const std::string& where, WriteErrors& err) {
  const std::string path = where + "/" + name;
  const hsize_t shape[3] = {frames.size(), static_cast<hsize_t>(height), static_cast<hsize_t>(width)};
  const hsize_t chunk[3] = {1, shape[1], shape[2]};
  // One chunk per frame under the deflate filter, no modification times, no chunk cache.
  const Hid space = Must(H5Screate_simple(3, shape, nullptr), H5Sclose, err, "cannot create " + path);
  const Hid dcpl = Must(H5Pcreate(H5P_DATASET_CREATE), H5Pclose, err, "cannot create " + path);
  MustOk(H5Pset_obj_track_times(dcpl.get(), 0), err, "cannot create " + path);
  MustOk(H5Pset_chunk(dcpl.get(), 3, chunk), err, "cannot chunk " + path);
  MustOk(H5Pset_deflate(dcpl.get(), kDeflateLevel), err, "cannot compress " + path);
  const Hid dapl = Must(H5Pcreate(H5P_DATASET_ACCESS), H5Pclose, err, "cannot create " + path);
  MustOk(H5Pset_chunk_cache(dapl.get(), 0, 0, H5D_CHUNK_CACHE_W0_DEFAULT), err, "cannot create " + path);
  const Hid dset = Must(H5Dcreate2(parent, name, H5T_STD_U8LE, space.get(), H5P_DEFAULT, dcpl.get(), dapl.get()),
                        H5Dclose, err, "cannot create " + path);
  // Each frame's compressed bytes as its chunk (filter mask 0: deflate applied).
  for (hsize_t k = 0; k < frames.size(); ++k) {
    const hsize_t offset[3] = {k, 0, 0};
    MustOk(H5Dwrite_chunk(dset.get(), H5P_DEFAULT, 0, offset, frames[k].size(), frames[k].data()), err,
           "cannot write " + path + " frame " + std::to_string(k));
  }
  WriteStringAttr(dset.get(), "units", "grey", path, err);
}

namespace {

/// Throws unless `dset` is chunked one whole frame per chunk under the deflate filter alone.
void CheckFrameChunks(hid_t dset, const std::vector<hsize_t>& shape, const std::string& source,
                      const std::string& where) {
  const Hid dcpl = Must(H5Dget_create_plist(dset), H5Pclose, source, "cannot read " + where);
  hsize_t chunk[3] = {0, 0, 0};
  const bool chunked = H5Pget_layout(dcpl.get()) == H5D_CHUNKED && H5Pget_chunk(dcpl.get(), 3, chunk) == 3;
  unsigned flags = 0;
  size_t n_values = 0;
  const bool deflate = H5Pget_nfilters(dcpl.get()) == 1 &&
                       H5Pget_filter2(dcpl.get(), 0, &flags, &n_values, nullptr, 0, nullptr, nullptr) ==
                           H5Z_FILTER_DEFLATE;
  if (!chunked || chunk[0] != 1 || chunk[1] != shape[1] || chunk[2] != shape[2] || !deflate) {
    throw InputError(source + where + " is not stored one deflate-compressed chunk per frame (chunks (1, " +
                     std::to_string(shape[1]) + ", " + std::to_string(shape[2]) + "), gzip)");
  }
}

}  // namespace

ImageStack ReadImageArray(hid_t dset, hsize_t frames, const std::string& source, const std::string& where) {
  // Shape (T, H, W) of uint8.
  const Hid space = Must(H5Dget_space(dset), H5Sclose, source, "cannot read " + where);
  std::vector<hsize_t> shape(3, 0);
  const Hid type = Must(H5Dget_type(dset), H5Tclose, source, "cannot read " + where);
  const bool bytes = H5Tget_class(type.get()) == H5T_INTEGER && H5Tget_size(type.get()) == 1 &&
                     H5Tget_sign(type.get()) == H5T_SGN_NONE;
  if (H5Sget_simple_extent_ndims(space.get()) != 3 || H5Sget_simple_extent_dims(space.get(), shape.data(), nullptr) < 0 ||
      shape[0] != frames || shape[1] < 1 || shape[2] < 1 || !bytes ||
      shape[1] > static_cast<hsize_t>(std::numeric_limits<int>::max() / 2) ||
      shape[2] > static_cast<hsize_t>(std::numeric_limits<int>::max() / 2)) {
    throw InputError(source + where + " has shape " + ShapeText(shape) + ", expected (" + std::to_string(frames) +
                     ", H, W) of uint8");
  }
  CheckFrameChunks(dset, shape, source, where);
  ImageStack out;
  out.height = static_cast<int>(shape[1]);
  out.width = static_cast<int>(shape[2]);
  // Each frame's chunk as stored; a chunk stored without the filter is compressed here.
  for (hsize_t k = 0; k < frames; ++k) {
    const hsize_t offset[3] = {k, 0, 0};
    hsize_t stored = 0;
    if (H5Dget_chunk_storage_size(dset, offset, &stored) < 0 || stored == 0) {
      throw InputError(source + where + " has no stored frame " + std::to_string(k));
    }
    CompressedFrame chunk(stored);
    std::uint32_t mask = 0;
    MustOk(H5Dread_chunk(dset, H5P_DEFAULT, offset, &mask, chunk.data()), source,
           "cannot read " + where + " frame " + std::to_string(k));
    if (mask != 0) chunk = CompressFrame(chunk.data(), chunk.size());
    out.frames.push_back(std::move(chunk));
  }
  return out;
}

}  // namespace tactip
