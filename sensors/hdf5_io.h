#pragma once
// The HDF5 C API as the dataset writer and reader use it: owned identifiers, one-line
// errors naming the file and what failed, attributes and arrays. Internal to sensors/.

#include <hdf5.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace tactip::hdf5 {

/// Frames per chunk (at most) of arrays that have a pin axis.
constexpr hsize_t kChunkFrames = 256;
/// zlib level of chunked arrays.
constexpr unsigned kDeflateLevel = 4;

/// Owns one HDF5 identifier and releases it with the matching close function.
class Hid {
 public:
  /// H5Fclose, H5Gclose, H5Dclose, ...
  using Closer = herr_t (*)(hid_t);

  Hid() = default;
  /// Takes ownership of `id` (which must be valid).
  Hid(hid_t id, Closer close) : id_(id), close_(close) {}
  Hid(Hid&& other) noexcept : id_(std::exchange(other.id_, H5I_INVALID_HID)), close_(other.close_) {}
  Hid& operator=(Hid&& other) noexcept {
    if (this != &other) {
      Close();
      id_ = std::exchange(other.id_, H5I_INVALID_HID);
      close_ = other.close_;
    }
    return *this;
  }
  Hid(const Hid&) = delete;
  Hid& operator=(const Hid&) = delete;
  ~Hid() { Close(); }

  /// The raw identifier (H5I_INVALID_HID when empty).
  hid_t get() const { return id_; }
  /// True while an identifier is owned.
  bool valid() const { return id_ >= 0; }
  /// Closes the identifier now; returns the close function's status (0 if empty).
  herr_t Close() {
    herr_t status = 0;
    if (id_ >= 0) status = close_(id_);
    id_ = H5I_INVALID_HID;
    return status;
  }

 private:
  hid_t id_ = H5I_INVALID_HID;
  Closer close_ = nullptr;
};

/// Silences HDF5's automatic error-stack printing for its lifetime and restores the
/// previous handler afterwards, so users see only our one-line InputError.
class QuietHdf5 {
 public:
  QuietHdf5() {
    restore_ = H5Eget_auto2(H5E_DEFAULT, &func_, &data_) >= 0;
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  }
  ~QuietHdf5() {
    if (restore_) H5Eset_auto2(H5E_DEFAULT, func_, data_);
  }
  QuietHdf5(const QuietHdf5&) = delete;
  QuietHdf5& operator=(const QuietHdf5&) = delete;

 private:
  H5E_auto2_t func_ = nullptr;
  void* data_ = nullptr;
  bool restore_ = false;
};


/// Innermost description on HDF5's error stack ("" if none), on one line.
std::string Hdf5Detail();

/// prefix + what, with HDF5's own reason in parentheses when it has one.
std::string FailureMessage(const std::string& prefix, const std::string& what);

/// Throws InputError(prefix + what), adding HDF5's own reason when it has one.
[[noreturn]] void Fail(const std::string& prefix, const std::string& what);

/// Wraps a freshly returned identifier, throwing via Fail() if the call failed.
Hid Must(hid_t id, Hid::Closer close, const std::string& prefix, const std::string& what);

/// Throws via Fail() if an HDF5 call returned a negative status.
void MustOk(herr_t status, const std::string& prefix, const std::string& what);

/// How writing a file fails: the message prefix ("cannot write dataset 'PATH': ") and the
/// file being written. A failure abandons the file and discards its pending writes before
/// throwing, so the identifiers closed while the exception unwinds cannot fail on a full
/// disk (see DiscardPendingWrites).
struct WriteErrors {
  std::string prefix;
  hid_t file = H5I_INVALID_HID;  ///< the file once created (not owned)
  bool failed = false;           ///< a write failed: the file will not be published

  /// Abandons the file and throws InputError(prefix + what).
  [[noreturn]] void Fail(const std::string& what);
};

/// Must() for the writer: a failure abandons the file.
Hid Must(hid_t id, Hid::Closer close, WriteErrors& err, const std::string& what);

/// MustOk() for the writer: a failure abandons the file.
void MustOk(herr_t status, WriteErrors& err, const std::string& what);

/// File and memory HDF5 types of an array element type.
template <class T>
struct H5Types;
template <>
struct H5Types<double> {
  static hid_t file() { return H5T_IEEE_F64LE; }
  static hid_t mem() { return H5T_NATIVE_DOUBLE; }
};
template <>
struct H5Types<float> {
  static hid_t file() { return H5T_IEEE_F32LE; }
  static hid_t mem() { return H5T_NATIVE_FLOAT; }
};
template <>
struct H5Types<std::uint8_t> {
  static hid_t file() { return H5T_STD_U8LE; }
  static hid_t mem() { return H5T_NATIVE_UINT8; }
};


/// Variable-length UTF-8 string type (what h5py reads as str).
Hid Utf8StringType(WriteErrors& err);

/// Group creation properties without modification times (keeps files byte-identical).
Hid UntimedGroupProps(WriteErrors& err);

/// Creates group `name` under `parent`; `where` is its full path for messages. An
/// `ordered` group remembers the order its members were created in (readers, h5py
/// included, list them in that order).
Hid CreateGroup(hid_t parent, const char* name, const std::string& where, WriteErrors& err, bool ordered = false);

/// Writes a scalar string attribute `name` = `value` on object `obj` (path `where`).
void WriteStringAttr(hid_t obj, const std::string& name, const std::string& value, const std::string& where,
                     WriteErrors& err);

/// Writes a scalar numeric attribute stored as `file_type`, read from `value` as `mem_type`.
void WriteScalarAttr(hid_t obj, const std::string& name, hid_t file_type, hid_t mem_type, const void* value,
                     const std::string& where, WriteErrors& err);

/// attribute. Arrays of rank > 1 (those with a pin axis) are chunked along frames and
/// deflate-compressed; 1-D arrays are contiguous.
template <class T>
void WriteArray(hid_t parent, const char* name, const std::vector<hsize_t>& shape, const std::vector<T>& data,
                const char* units, const std::string& where, WriteErrors& err) {
  const std::string path = where + "/" + name;
  const int rank = static_cast<int>(shape.size());
  const Hid space = Must(H5Screate_simple(rank, shape.data(), nullptr), H5Sclose, err, "cannot create " + path);
  const Hid dcpl = Must(H5Pcreate(H5P_DATASET_CREATE), H5Pclose, err, "cannot create " + path);
  MustOk(H5Pset_obj_track_times(dcpl.get(), 0), err, "cannot create " + path);
  if (shape.size() > 1) {
    // Chunk = up to kChunkFrames whole frames.
    std::vector<hsize_t> chunk = shape;
    chunk[0] = std::min(shape[0], kChunkFrames);
    MustOk(H5Pset_chunk(dcpl.get(), rank, chunk.data()), err, "cannot chunk " + path);
    MustOk(H5Pset_deflate(dcpl.get(), kDeflateLevel), err, "cannot compress " + path);
  }
  // No chunk cache: H5Dwrite writes every chunk itself and reports a failure, instead of
  // the close doing it (HDF5 1.10 cannot recover from a failed H5Dclose).
  const Hid dapl = Must(H5Pcreate(H5P_DATASET_ACCESS), H5Pclose, err, "cannot create " + path);
  MustOk(H5Pset_chunk_cache(dapl.get(), 0, 0, H5D_CHUNK_CACHE_W0_DEFAULT), err, "cannot create " + path);
  const Hid dset = Must(H5Dcreate2(parent, name, H5Types<T>::file(), space.get(), H5P_DEFAULT, dcpl.get(), dapl.get()),
                        H5Dclose, err, "cannot create " + path);
  if (!data.empty()) {  // an array of no values has nothing to write
    MustOk(H5Dwrite(dset.get(), H5Types<T>::mem(), H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()), err,
           "cannot write " + path);
  }
  WriteStringAttr(dset.get(), "units", units, path, err);
}


/// Writes a 1-D attribute `name` of variable-length UTF-8 strings on `obj` (path `where`).
void WriteStringListAttr(hid_t obj, const std::string& name, const std::vector<std::string>& values,
                         const std::string& where, WriteErrors& err);

/// Writes a 1-D contiguous array `name` of variable-length UTF-8 strings under `parent`
/// (path `where`).
void WriteStringArray(hid_t parent, const char* name, const std::vector<std::string>& values,
                      const std::string& where, WriteErrors& err);

/// Object kinds of an attribute as far as the reader cares.
enum class AttrKind { kNumber, kString, kOther };

/// Classifies attribute `attr`: scalar (or one-element) number, scalar string, other.
AttrKind KindOf(hid_t attr, const std::string& err, const std::string& what);

/// Reads a one-element string attribute, variable- or fixed-length.
std::string ReadStringAttr(hid_t attr, const std::string& err, const std::string& what);

/// Reads a 1-D attribute or array `obj` of variable-length strings (`is_attr`: an
/// attribute, else an array); throws InputError "<err>: <where> is not a list of strings"
/// for any other type.
std::vector<std::string> ReadStringList(hid_t obj, bool is_attr, const std::string& err, const std::string& where);

/// Names of the members of group `group`: in creation order when the group tracks it,
/// else in name order.
std::vector<std::string> MemberNames(hid_t group, const std::string& err, const std::string& what);

/// Names of all attributes of `obj`, in name order.
std::vector<std::string> AttrNames(hid_t obj, const std::string& err, const std::string& what);

/// "(5, 3, 2)".
std::string ShapeText(const std::vector<hsize_t>& shape);

}  // namespace tactip::hdf5
