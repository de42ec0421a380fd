#include "sensors/dataset.h"

#include <fcntl.h>
#include <hdf5.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
#include <memory>
#include <stdexcept>
#include <utility>

#include "sensors/hdf5_discard.h"
#include "sensors/run_checks.h"
#include "sim/config.h"
#include "sim/base/files.h"

namespace tactip {
namespace {

/// Frames per chunk (at most) of arrays that have a pin axis.
constexpr hsize_t kChunkFrames = 256;
/// zlib level of chunked arrays.
constexpr unsigned kDeflateLevel = 4;
/// Bytes that must be free when a file is created: more than H5Fcreate writes.
constexpr long long kHeaderRoom = 16 * 1024;

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
std::string Hdf5Detail() {
  std::string detail;
  auto visit = [](unsigned, const H5E_error2_t* err, void* out) -> herr_t {
    if (err->desc == nullptr || err->desc[0] == '\0') return 0;
    try {
      *static_cast<std::string*>(out) = err->desc;
    } catch (...) {
      return -1;
    }
    return 1;  // stop at the most specific entry
  };
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, visit, &detail);
  std::replace(detail.begin(), detail.end(), '\n', ' ');
  // The POSIX driver's reports ("file write failed: time = ..., errno = 28, error message =
  // 'No space left on device', buf = ...") carry a clock time and addresses: keep the reason.
  constexpr std::string_view kReason = "error message = '";
  const size_t colon = detail.find(':');
  const size_t at = detail.find(kReason);
  const size_t end = at == std::string::npos ? at : detail.find('\'', at + kReason.size());
  if (colon != std::string::npos && end != std::string::npos && colon < at) {
    detail = detail.substr(0, colon + 1) + " " + detail.substr(at + kReason.size(), end - at - kReason.size());
  }
  return detail;
}

/// prefix + what, with HDF5's own reason in parentheses when it has one.
std::string FailureMessage(const std::string& prefix, const std::string& what) {
  const std::string detail = Hdf5Detail();
  return prefix + what + (detail.empty() ? "" : " (" + detail + ")");
}

/// Throws InputError(prefix + what), adding HDF5's own reason when it has one.
[[noreturn]] void Fail(const std::string& prefix, const std::string& what) {
  throw InputError(FailureMessage(prefix, what));
}

/// Wraps a freshly returned identifier, throwing via Fail() if the call failed.
Hid Must(hid_t id, Hid::Closer close, const std::string& prefix, const std::string& what) {
  if (id < 0) Fail(prefix, what);
  return Hid(id, close);
}

/// Throws via Fail() if an HDF5 call returned a negative status.
void MustOk(herr_t status, const std::string& prefix, const std::string& what) {
  if (status < 0) Fail(prefix, what);
}

/// How writing a file fails: the message prefix ("cannot write dataset 'PATH': ") and the
/// file being written. A failure abandons the file and discards its pending writes before
/// throwing, so the identifiers closed while the exception unwinds cannot fail on a full
/// disk (see DiscardPendingWrites).
struct WriteErrors {
  std::string prefix;
  hid_t file = H5I_INVALID_HID;  ///< the file once created (not owned)
  bool failed = false;           ///< a write failed: the file will not be published

  [[noreturn]] void Fail(const std::string& what) {
    const std::string message = FailureMessage(prefix, what);  // before HDF5's error stack changes
    failed = true;
    DiscardPendingWrites(file);
    throw InputError(message);
  }
};

/// Must() for the writer: a failure abandons the file.
Hid Must(hid_t id, Hid::Closer close, WriteErrors& err, const std::string& what) {
  if (id < 0) err.Fail(what);
  return Hid(id, close);
}

/// MustOk() for the writer: a failure abandons the file.
void MustOk(herr_t status, WriteErrors& err, const std::string& what) {
  if (status < 0) err.Fail(what);
}

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
Hid Utf8StringType(WriteErrors& err) {
  Hid type = Must(H5Tcopy(H5T_C_S1), H5Tclose, err, "cannot create string type");
  MustOk(H5Tset_size(type.get(), H5T_VARIABLE), err, "cannot create string type");
  MustOk(H5Tset_cset(type.get(), H5T_CSET_UTF8), err, "cannot create string type");
  return type;
}

/// Group creation properties without modification times (keeps files byte-identical).
Hid UntimedGroupProps(WriteErrors& err) {
  Hid gcpl = Must(H5Pcreate(H5P_GROUP_CREATE), H5Pclose, err, "cannot create group properties");
  MustOk(H5Pset_obj_track_times(gcpl.get(), 0), err, "cannot disable group times");
  return gcpl;
}

/// Creates group `name` under `parent`; `where` is its full path for messages.
Hid CreateGroup(hid_t parent, const char* name, const std::string& where, WriteErrors& err) {
  const Hid gcpl = UntimedGroupProps(err);
  return Must(H5Gcreate2(parent, name, H5P_DEFAULT, gcpl.get(), H5P_DEFAULT), H5Gclose, err,
              "cannot create group " + where);
}

/// Writes a scalar string attribute `name` = `value` on object `obj` (path `where`).
void WriteStringAttr(hid_t obj, const std::string& name, const std::string& value, const std::string& where,
                     WriteErrors& err) {
  const std::string what = "cannot write attribute '" + name + "' of " + where;
  const Hid type = Utf8StringType(err);
  const Hid space = Must(H5Screate(H5S_SCALAR), H5Sclose, err, what);
  const Hid attr = Must(H5Acreate2(obj, name.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose,
                        err, what);
  const char* text = value.c_str();
  MustOk(H5Awrite(attr.get(), type.get(), &text), err, what);
}

/// Writes a scalar numeric attribute stored as `file_type`, read from `value` as `mem_type`.
void WriteScalarAttr(hid_t obj, const std::string& name, hid_t file_type, hid_t mem_type, const void* value,
                     const std::string& where, WriteErrors& err) {
  const std::string what = "cannot write attribute '" + name + "' of " + where;
  const Hid space = Must(H5Screate(H5S_SCALAR), H5Sclose, err, what);
  const Hid attr =
      Must(H5Acreate2(obj, name.c_str(), file_type, space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose, err, what);
  MustOk(H5Awrite(attr.get(), mem_type, value), err, what);
}

/// Writes array `name` of shape `shape` under `parent` (path `where`) with a "units"
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
  MustOk(H5Dwrite(dset.get(), H5Types<T>::mem(), H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()), err,
         "cannot write " + path);
  WriteStringAttr(dset.get(), "units", units, path, err);
}

/// Object kinds of an attribute as far as the reader cares.
enum class AttrKind { kNumber, kString, kOther };

/// Classifies attribute `attr`: scalar (or one-element) number, scalar string, other.
AttrKind KindOf(hid_t attr, const std::string& err, const std::string& what) {
  const Hid type = Must(H5Aget_type(attr), H5Tclose, err, what);
  const Hid space = Must(H5Aget_space(attr), H5Sclose, err, what);
  const hssize_t points = H5Sget_simple_extent_npoints(space.get());
  if (points != 1) return AttrKind::kOther;
  switch (H5Tget_class(type.get())) {
    case H5T_INTEGER:
    case H5T_FLOAT:
      return AttrKind::kNumber;
    case H5T_STRING:
      return AttrKind::kString;
    default:
      return AttrKind::kOther;
  }
}

/// Reads a one-element string attribute, variable- or fixed-length.
std::string ReadStringAttr(hid_t attr, const std::string& err, const std::string& what) {
  const Hid file_type = Must(H5Aget_type(attr), H5Tclose, err, what);
  const htri_t variable = H5Tis_variable_str(file_type.get());
  MustOk(variable, err, what);
  if (variable > 0) {
    // Variable length: HDF5 allocates the text; release it with H5free_memory.
    Hid mem_type = Must(H5Tcopy(H5T_C_S1), H5Tclose, err, what);
    MustOk(H5Tset_size(mem_type.get(), H5T_VARIABLE), err, what);
    MustOk(H5Tset_cset(mem_type.get(), H5Tget_cset(file_type.get())), err, what);
    char* text = nullptr;
    MustOk(H5Aread(attr, mem_type.get(), &text), err, what);
    const std::unique_ptr<char, herr_t (*)(void*)> owner(text, H5free_memory);
    return text != nullptr ? std::string(text) : std::string();
  }
  // Fixed length: read the raw bytes and strip the padding.
  const size_t size = H5Tget_size(file_type.get());
  if (size == 0) Fail(err, what);
  std::string text(size, '\0');
  MustOk(H5Aread(attr, file_type.get(), text.data()), err, what);
  if (H5Tget_strpad(file_type.get()) == H5T_STR_SPACEPAD) {
    text.erase(text.find_last_not_of(' ') + 1);
  } else {
    text.resize(std::strlen(text.c_str()));
  }
  return text;
}

/// Names of all attributes of `obj`, in name order.
std::vector<std::string> AttrNames(hid_t obj, const std::string& err, const std::string& what) {
  std::vector<std::string> names;
  auto collect = [](hid_t, const char* name, const H5A_info_t*, void* out) -> herr_t {
    try {
      static_cast<std::vector<std::string>*>(out)->emplace_back(name);
    } catch (...) {
      return -1;
    }
    return 0;
  };
  MustOk(H5Aiterate2(obj, H5_INDEX_NAME, H5_ITER_INC, nullptr, collect, &names), err, what);
  return names;
}

/// Run index encoded in a /runs child name, or -1 if it is not a canonical run_NNNN.
int ParseRunName(const std::string& name) {
  constexpr std::string_view kPrefix = "run_";
  if (name.size() < kPrefix.size() + 4 || name.compare(0, kPrefix.size(), kPrefix) != 0) return -1;
  int index = -1;
  const char* begin = name.data() + kPrefix.size();
  const char* end = name.data() + name.size();
  const auto res = std::from_chars(begin, end, index);
  if (res.ec != std::errc() || res.ptr != end || index < 0) return -1;
  return RunGroupName(index) == name ? index : -1;
}

/// Index of the first non-finite value of `v`, or -1.
template <class T>
long long FirstNonFinite(const std::vector<T>& v) {
  for (size_t k = 0; k < v.size(); ++k) {
    if (!std::isfinite(static_cast<double>(v[k]))) return static_cast<long long>(k);
  }
  return -1;
}

/// Throws InputError (prefix `err`) naming the first array of `run` that holds a non-finite
/// value, with its frame and pin: such a value is no data, and a file must not carry it.
void CheckFinite(const RunRecord& run, const std::string& err) {
  struct Array {
    const char* path;
    long long bad;
    size_t per_frame, per_pin;  // values per frame and per pin (0: no pin axis)
  };
  const size_t n = static_cast<size_t>(run.n_pins);
  const Array arrays[] = {
      {"time", FirstNonFinite(run.time), 1, 0},
      {"pins/pos_px", FirstNonFinite(run.pos_px), 2 * n, 2},
      {"pins/pos_m", FirstNonFinite(run.pos_m), 3 * n, 3},
      {"external/pos_px", FirstNonFinite(run.external_px), 2 * n, 2},
      {"external/pos_m", FirstNonFinite(run.external_m), 3 * n, 3},
      {"contact/normal_N", FirstNonFinite(run.normal_N), n, 1},
      {"contact/tangential_N", FirstNonFinite(run.tangential_N), 2 * n, 2},
      {"object/height_m", FirstNonFinite(run.object_height_m), 1, 0},
  };
  for (const Array& a : arrays) {
    if (a.bad < 0) continue;
    const size_t k = static_cast<size_t>(a.bad);
    std::string where = "frame " + std::to_string(k / a.per_frame);
    if (a.per_pin > 0) where += ", pin " + std::to_string((k % a.per_frame) / a.per_pin);
    throw InputError(err + "/runs/" + RunGroupName(run.index) + "/" + a.path + " would hold a non-finite value (" +
                     where + "); the run is not written");
  }
}

/// "(5, 3, 2)".
std::string ShapeText(const std::vector<hsize_t>& shape) {
  std::string out = "(";
  for (size_t i = 0; i < shape.size(); ++i) out += (i ? ", " : "") + std::to_string(shape[i]);
  return out + ")";
}

}  // namespace

// ---------------------------------------------------------------------------------------
// RunRecord

void RunRecord::CheckShapes() const {
  const std::string who = "RunRecord " + RunGroupName(index) + ": ";
  if (index < 0) throw std::logic_error("RunRecord: index must be >= 0, got " + std::to_string(index));
  if (time.empty()) throw std::logic_error(who + "time is empty (need T >= 1 frames)");
  if (n_pins < 1) throw std::logic_error(who + "n_pins must be >= 1, got " + std::to_string(n_pins));
  const size_t t = time.size();
  const size_t n = static_cast<size_t>(n_pins);
  const std::string dims = " (T=" + std::to_string(t) + ", N=" + std::to_string(n) + ")";
  // Each field against the product of its shape.
  auto check = [&](const char* field, size_t actual, size_t expected, const char* shape) {
    if (actual != expected) {
      throw std::logic_error(who + field + " has " + std::to_string(actual) + " values, expected " +
                             std::to_string(expected) + " = " + shape + dims);
    }
  };
  check("pos_px", pos_px.size(), t * n * 2, "T*N*2");
  check("valid", valid.size(), t * n, "T*N");
  check("pos_m", pos_m.size(), t * n * 3, "T*N*3");
  check("gross_slip", gross_slip.size(), t, "T");
  check("pin_slip", pin_slip.size(), t * n, "T*N");
  check("pin_contact", pin_contact.size(), t * n, "T*N");
  check("normal_N", normal_N.size(), t * n, "T*N");
  check("tangential_N", tangential_N.size(), t * n * 2, "T*N*2");
  check("object_height_m", object_height_m.size(), t, "T");
  check("incipient", incipient.size(), t, "T");
  if (!external_px.empty() || !external_m.empty()) {
    check("external_px", external_px.size(), t * n * 2, "T*N*2");
    check("external_m", external_m.size(), t * n * 3, "T*N*3");
  }
}

std::vector<std::uint8_t> PartialSlipLabels(const std::vector<std::uint8_t>& pin_contact,
                                            const std::vector<std::uint8_t>& pin_slip, int n_pins) {
  const size_t n = static_cast<size_t>(n_pins);
  std::vector<std::uint8_t> out(n == 0 ? 0 : pin_contact.size() / n, 0);
  for (size_t f = 0; f < out.size(); ++f) {
    int contact = 0, slip = 0;
    for (size_t i = 0; i < n; ++i) {
      contact += pin_contact[f * n + i];
      slip += pin_contact[f * n + i] && pin_slip[f * n + i];
    }
    out[f] = slip > 0 && slip < contact ? 1 : 0;
  }
  return out;
}

std::string RunGroupName(int index) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "run_%04d", index);
  return buf;
}

// ---------------------------------------------------------------------------------------
// DatasetWriter

/// Open temporary file; removes it on destruction unless `keep` was set by Commit().
struct DatasetWriter::Impl {
  std::string temp_path;   ///< file to delete
  bool created = false;    ///< we created temp_path (so we may delete it)
  bool keep = false;       ///< renamed into place: do not delete
  WriteErrors err;         ///< "cannot write dataset 'PATH': ", and whether a write failed
  Hid file;                ///< temporary HDF5 file
  Hid runs;                ///< its /runs group

  ~Impl() {
    const QuietHdf5 quiet;
    // The file is deleted unless committed: closing it must not write (or fail on) the disk.
    if (!keep) DiscardPendingWrites(file.get());
    runs.Close();
    file.Close();
    if (created && !keep) std::remove(temp_path.c_str());
  }
};

DatasetWriter::DatasetWriter(const std::string& path, const DatasetHeader& header)
    : impl_(std::make_unique<Impl>()), path_(path), temp_path_(TempPathFor(path)) {
  const QuietHdf5 quiet;
  Impl& im = *impl_;
  im.temp_path = temp_path_;
  im.err.prefix = "cannot write dataset '" + path + "': ";
  namespace fs = std::filesystem;
  std::error_code ec;
  if (path.empty()) throw InputError("cannot write dataset '': empty path");
  if (fs::is_directory(path, ec)) throw InputError(im.err.prefix + "is a directory");

  // Create the temporary file ourselves first, so errno says why a folder is unusable.
  const int fd = ::open(temp_path_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) {
    const int why = errno;
    const std::string parent = fs::path(path).parent_path().string();
    const std::string folder = parent.empty() ? "." : parent;
    // ENOENT also comes from folders that exist but take no new files (such as /proc).
    if (why == ENOENT && !fs::is_directory(folder, ec)) {
      throw InputError(im.err.prefix + "folder '" + folder + "' does not exist");
    }
    throw InputError(im.err.prefix + "cannot create a file in folder '" + folder + "' (" + std::strerror(why) + ")");
  }
  ::close(fd);
  im.created = true;
  // A disk without room for the file's header fails here: HDF5 1.10 leaks memory when
  // H5Fcreate itself cannot write (H5Fcreate truncates the file, releasing the room again).
  if (const int why = ReserveFileSpace(temp_path_, kHeaderRoom); why != 0) {
    throw InputError(im.err.prefix + std::strerror(why));
  }

  // No modification times anywhere (root group included); format readable by HDF5 >= 1.8.
  const Hid fcpl = Must(H5Pcreate(H5P_FILE_CREATE), H5Pclose, im.err, "cannot create file properties");
  MustOk(H5Pset_obj_track_times(fcpl.get(), 0), im.err, "cannot disable root group times");
  const Hid fapl = Must(H5Pcreate(H5P_FILE_ACCESS), H5Pclose, im.err, "cannot create file properties");
  MustOk(H5Pset_libver_bounds(fapl.get(), H5F_LIBVER_EARLIEST, H5F_LIBVER_V18), im.err, "cannot set format");
  MustOk(H5Pset_fclose_degree(fapl.get(), H5F_CLOSE_STRONG), im.err, "cannot set close degree");
  MustOk(H5Pset_fapl_sec2(fapl.get()), im.err, "cannot set file driver");  // what DiscardPendingWrites redirects
  // No sieve buffer: H5Dwrite writes contiguous arrays itself (see WriteArray).
  MustOk(H5Pset_sieve_buf_size(fapl.get(), 0), im.err, "cannot set sieve buffer");
  im.file = Must(H5Fcreate(temp_path_.c_str(), H5F_ACC_TRUNC, fcpl.get(), fapl.get()), H5Fclose, im.err,
                 "cannot create HDF5 file '" + temp_path_ + "'");
  im.err.file = im.file.get();

  // Root attributes, then the (possibly empty) /runs group.
  const hid_t root = im.file.get();
  WriteStringAttr(root, "tactip_version", header.tactip_version, "/", im.err);
  WriteStringAttr(root, "scenario", header.scenario, "/", im.err);
  WriteScalarAttr(root, "seed", H5T_STD_U64LE, H5T_NATIVE_UINT64, &header.seed, "/", im.err);
  WriteStringAttr(root, "config_yaml", header.config_yaml, "/", im.err);
  if (header.shard) {
    // Shard files only, after the common attributes: a merged file has none of these.
    const std::uint64_t runs_total = static_cast<std::uint64_t>(header.shard->runs_total);
    WriteStringAttr(root, "shard", header.shard->text(), "/", im.err);
    WriteScalarAttr(root, "runs_total", H5T_STD_U64LE, H5T_NATIVE_UINT64, &runs_total, "/", im.err);
  }
  im.runs = CreateGroup(root, "runs", "/runs", im.err);
}

DatasetWriter::~DatasetWriter() = default;

void DatasetWriter::WriteRun(const RunRecord& run) {
  if (committed_ || !impl_ || !impl_->file.valid()) {
    throw std::logic_error("DatasetWriter::WriteRun called after Commit for '" + path_ + "'");
  }
  if (impl_->err.failed) throw std::logic_error("DatasetWriter::WriteRun called after a failed write to '" + path_ + "'");
  run.CheckShapes();
  CheckFinite(run, impl_->err.prefix);
  for (const auto& [key, value] : run.text_attrs) {
    if (run.attrs.count(key) != 0) {
      throw std::logic_error("RunRecord " + RunGroupName(run.index) + ": attribute '" + key +
                             "' is both numeric and text");
    }
  }
  const QuietHdf5 quiet;
  Impl& im = *impl_;
  const std::string name = RunGroupName(run.index);
  const std::string where = "/runs/" + name;
  if (H5Lexists(im.runs.get(), name.c_str(), H5P_DEFAULT) > 0) {
    throw std::logic_error("DatasetWriter: " + name + " written twice to '" + path_ + "'");
  }

  try {
    const Hid group = CreateGroup(im.runs.get(), name.c_str(), where, im.err);
    const hid_t g = group.get();
    // Attributes in name order (std::map), numeric then text.
    for (const auto& [key, value] : run.attrs) {
      WriteScalarAttr(g, key, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &value, where, im.err);
    }
    for (const auto& [key, value] : run.text_attrs) WriteStringAttr(g, key, value, where, im.err);

    const hsize_t t = run.frames();
    const hsize_t n = static_cast<hsize_t>(run.n_pins);
    WriteArray(g, "time", {t}, run.time, "s", where, im.err);
    {
      const Hid pins = CreateGroup(g, "pins", where + "/pins", im.err);
      WriteArray(pins.get(), "pos_px", {t, n, 2}, run.pos_px, "px", where + "/pins", im.err);
      WriteArray(pins.get(), "valid", {t, n}, run.valid, "1", where + "/pins", im.err);
      WriteArray(pins.get(), "pos_m", {t, n, 3}, run.pos_m, "m", where + "/pins", im.err);
    }
    {
      const Hid labels = CreateGroup(g, "labels", where + "/labels", im.err);
      WriteArray(labels.get(), "gross_slip", {t}, run.gross_slip, "1", where + "/labels", im.err);
      WriteArray(labels.get(), "pin_slip", {t, n}, run.pin_slip, "1", where + "/labels", im.err);
      WriteArray(labels.get(), "pin_contact", {t, n}, run.pin_contact, "1", where + "/labels", im.err);
      WriteArray(labels.get(), "incipient", {t}, run.incipient, "1", where + "/labels", im.err);
    }
    if (!run.external_px.empty()) {
      const Hid ext = CreateGroup(g, "external", where + "/external", im.err);
      WriteArray(ext.get(), "pos_px", {t, n, 2}, run.external_px, "px", where + "/external", im.err);
      WriteArray(ext.get(), "pos_m", {t, n, 3}, run.external_m, "m", where + "/external", im.err);
    }
    {
      const Hid contact = CreateGroup(g, "contact", where + "/contact", im.err);
      WriteArray(contact.get(), "normal_N", {t, n}, run.normal_N, "N", where + "/contact", im.err);
      WriteArray(contact.get(), "tangential_N", {t, n, 2}, run.tangential_N, "N", where + "/contact", im.err);
    }
    {
      const Hid object = CreateGroup(g, "object", where + "/object", im.err);
      WriteArray(object.get(), "height_m", {t}, run.object_height_m, "m", where + "/object", im.err);
    }
  } catch (...) {
    // Unlink the partial run so a later Commit never publishes it.
    H5Ldelete(im.runs.get(), name.c_str(), H5P_DEFAULT);
    throw;
  }
}

void DatasetWriter::Commit() {
  if (committed_ || !impl_ || !impl_->file.valid()) {
    throw std::logic_error("DatasetWriter::Commit called twice for '" + path_ + "'");
  }
  if (impl_->err.failed) throw std::logic_error("DatasetWriter::Commit called after a failed write to '" + path_ + "'");
  Impl& im = *impl_;
  {
    const QuietHdf5 quiet;
    // Closing writes the cached metadata, and HDF5 1.10 cannot recover from a failed close:
    // reserve the disk space of the whole file first, so a full disk fails here, with the
    // file still open for ~Impl to abandon and delete.
    MustOk(im.runs.Close(), im.err, "cannot close /runs");
    hsize_t size = 0;
    MustOk(H5Fget_filesize(im.file.get(), &size), im.err, "cannot size '" + temp_path_ + "'");
    if (const int why = ReserveFileSpace(temp_path_, static_cast<long long>(size)); why != 0) {
      im.err.Fail("cannot write '" + temp_path_ + "': " + std::strerror(why));
    }
    im.err.file = H5I_INVALID_HID;  // not to be touched after its close, even a failed one
    MustOk(im.file.Close(), im.err.prefix, "cannot close '" + temp_path_ + "'");
  }
  // Make the bytes durable before the rename publishes them.
  const int fd = ::open(temp_path_.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0 || ::fsync(fd) != 0) {
    const int why = errno;
    if (fd >= 0) ::close(fd);
    throw InputError(im.err.prefix + "cannot sync '" + temp_path_ + "': " + std::strerror(why));
  }
  ::close(fd);
  if (std::rename(temp_path_.c_str(), path_.c_str()) != 0) {
    const int why = errno;
    throw InputError(im.err.prefix + "cannot rename '" + temp_path_ + "': " + std::strerror(why));
  }
  im.keep = true;
  impl_.reset();
  committed_ = true;
}

// ---------------------------------------------------------------------------------------
// DatasetReader

/// Open file plus the helpers that turn HDF5 failures into InputErrors naming it.
struct DatasetReader::Impl {
  std::string path;  ///< as given by the caller
  std::string err;   ///< "cannot read dataset 'PATH': "
  Hid file;          ///< read-only file
  Hid runs;          ///< its /runs group

  ~Impl() {
    const QuietHdf5 quiet;
    runs.Close();
    file.Close();
  }

  /// "dataset 'PATH'" for messages.
  std::string Name() const { return "dataset '" + path + "'"; }

  /// Opens root attribute `name`, throwing if it is missing.
  Hid OpenRootAttr(const char* name) const {
    if (H5Aexists(file.get(), name) <= 0) {
      throw InputError(Name() + " has no root attribute '" + name + "'");
    }
    return Must(H5Aopen(file.get(), name, H5P_DEFAULT), H5Aclose, err, std::string("cannot open attribute ") + name);
  }

  /// Reads required string root attribute `name`.
  std::string RootString(const char* name) const {
    const Hid attr = OpenRootAttr(name);
    const std::string what = std::string("cannot read attribute '") + name + "'";
    if (KindOf(attr.get(), err, what) != AttrKind::kString) {
      throw InputError(Name() + ": root attribute '" + name + "' is not a string");
    }
    return ReadStringAttr(attr.get(), err, what);
  }

  /// Reads required unsigned integer root attribute `name`.
  std::uint64_t RootUint64(const char* name) const {
    const Hid attr = OpenRootAttr(name);
    const std::string what = std::string("cannot read attribute '") + name + "'";
    const Hid type = Must(H5Aget_type(attr.get()), H5Tclose, err, what);
    if (KindOf(attr.get(), err, what) != AttrKind::kNumber || H5Tget_class(type.get()) != H5T_INTEGER) {
      throw InputError(Name() + ": root attribute '" + name + "' is not an integer");
    }
    std::uint64_t value = 0;
    MustOk(H5Aread(attr.get(), H5T_NATIVE_UINT64, &value), err, what);
    return value;
  }

  /// Reads the optional shard attributes (`shard` = "i/n" with `runs_total` = R), which
  /// must be present together and consistent.
  std::optional<ShardSpec> RootShard() const {
    if (H5Aexists(file.get(), "shard") <= 0) {
      if (H5Aexists(file.get(), "runs_total") > 0) {
        throw InputError(Name() + " has root attribute 'runs_total' but no 'shard'");
      }
      return std::nullopt;
    }
    const std::string text = RootString("shard");
    const std::uint64_t runs_total = RootUint64("runs_total");
    if (runs_total < 1 || runs_total > static_cast<std::uint64_t>(std::numeric_limits<int>::max())) {
      throw InputError(Name() + ": root attribute 'runs_total' = " + std::to_string(runs_total) +
                       " is out of range");
    }
    ShardSpec spec;
    const std::string problem = ParseShard(text, static_cast<int>(runs_total), spec);
    if (!problem.empty()) {
      throw InputError(Name() + ": root attribute 'shard' = '" + text + "' is invalid: " + problem);
    }
    return spec;
  }

  /// Opens group /runs/run_NNNN; `runs` lists the indices present.
  Hid OpenRun(int index, const std::vector<int>& present) const {
    const std::string name = RunGroupName(index);
    if (!std::binary_search(present.begin(), present.end(), index)) {
      throw InputError(Name() + " has no run " + name);
    }
    return Must(H5Gopen2(runs.get(), name.c_str(), H5P_DEFAULT), H5Gclose, err, "cannot open /runs/" + name);
  }

  /// Opens array `rel` (e.g. "pins/pos_px") of run group `group`.
  /// True if the run has the (optional) array `rel`.
  static bool HasArray(hid_t group, const std::string& rel) {
    size_t slash = 0;
    // Every link on the path must exist (H5Lexists fails on a missing parent).
    while ((slash = rel.find('/', slash + 1)) != std::string::npos) {
      if (H5Lexists(group, rel.substr(0, slash).c_str(), H5P_DEFAULT) <= 0) return false;
    }
    return H5Lexists(group, rel.c_str(), H5P_DEFAULT) > 0;
  }

  Hid OpenArray(hid_t group, const std::string& run, const char* rel) const {
    const hid_t id = H5Dopen2(group, rel, H5P_DEFAULT);
    if (id < 0) throw InputError(Name() + ": " + run + " has no array " + rel);
    return Hid(id, H5Dclose);
  }

  /// Shape of an open array.
  std::vector<hsize_t> ShapeOf(hid_t dset, const std::string& what) const {
    const Hid space = Must(H5Dget_space(dset), H5Sclose, err, what);
    const int rank = H5Sget_simple_extent_ndims(space.get());
    if (rank < 0) Fail(err, what);
    std::vector<hsize_t> shape(static_cast<size_t>(rank));
    MustOk(H5Sget_simple_extent_dims(space.get(), shape.data(), nullptr), err, what);
    return shape;
  }

  /// Reads array `rel` of run `run`, which must have shape `expected`.
  template <class T>
  std::vector<T> ReadArray(hid_t group, const std::string& run, const char* rel,
                           const std::vector<hsize_t>& expected) const {
    const std::string what = "cannot read /runs/" + run + "/" + rel;
    const Hid dset = OpenArray(group, run, rel);
    const std::vector<hsize_t> shape = ShapeOf(dset.get(), what);
    if (shape != expected) {
      throw InputError(Name() + ": " + run + "/" + rel + " has shape " + ShapeText(shape) + ", expected " +
                       ShapeText(expected));
    }
    size_t count = 1;
    for (hsize_t d : shape) count *= static_cast<size_t>(d);
    std::vector<T> out(count);
    if (count > 0) {
      MustOk(H5Dread(dset.get(), H5Types<T>::mem(), H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()), err, what);
    }
    return out;
  }

  /// Reads what ReadRunSummary returns: index, attributes, time and n_pins.
  RunRecord ReadSummary(hid_t group, int index) const {
    RunRecord run;
    run.index = index;
    const std::string name = RunGroupName(index);
    const std::string what = "cannot read attributes of /runs/" + name;
    // Every scalar attribute: numbers as double, strings as text; others are ignored.
    for (const std::string& key : AttrNames(group, err, what)) {
      const Hid attr = Must(H5Aopen(group, key.c_str(), H5P_DEFAULT), H5Aclose, err, what);
      switch (KindOf(attr.get(), err, what)) {
        case AttrKind::kNumber: {
          double value = 0.0;
          MustOk(H5Aread(attr.get(), H5T_NATIVE_DOUBLE, &value), err, what);
          run.attrs[key] = value;
          break;
        }
        case AttrKind::kString:
          run.text_attrs[key] = ReadStringAttr(attr.get(), err, what);
          break;
        case AttrKind::kOther:
          break;
      }
    }
    // T from time (1-D), N from pins/valid (T, N); only the shape of pins/valid is read.
    const Hid time = OpenArray(group, name, "time");
    const std::vector<hsize_t> tshape = ShapeOf(time.get(), "cannot read /runs/" + name + "/time");
    if (tshape.size() != 1) {
      throw InputError(Name() + ": " + name + "/time has shape " + ShapeText(tshape) + ", expected (T)");
    }
    run.time = ReadArray<double>(group, name, "time", tshape);
    const Hid valid = OpenArray(group, name, "pins/valid");
    const std::vector<hsize_t> vshape = ShapeOf(valid.get(), "cannot read /runs/" + name + "/pins/valid");
    if (vshape.size() != 2 || vshape[0] != tshape[0] || vshape[1] < 1 ||
        vshape[1] > static_cast<hsize_t>(std::numeric_limits<int>::max())) {
      throw InputError(Name() + ": " + name + "/pins/valid has shape " + ShapeText(vshape) + ", expected (" +
                       std::to_string(tshape[0]) + ", N)");
    }
    run.n_pins = static_cast<int>(vshape[1]);
    CheckRunTimes(run, Name());
    return run;
  }
};

DatasetReader::DatasetReader(const std::string& path) : impl_(std::make_unique<Impl>()) {
  const QuietHdf5 quiet;
  Impl& im = *impl_;
  im.path = path;
  im.err = "cannot read dataset '" + path + "': ";
  const std::string open_err = "cannot open dataset '" + path + "': ";

  // Plain file checks first, for precise messages.
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_type kind = fs::status(path, ec).type();
  if (kind == fs::file_type::not_found) throw InputError(open_err + "no such file");
  if (kind == fs::file_type::directory) throw InputError(open_err + "is a directory");
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw InputError(open_err + std::strerror(errno));
  ::close(fd);
#if H5_VERSION_GE(1, 12, 0)
  const htri_t is_hdf5 = H5Fis_accessible(path.c_str(), H5P_DEFAULT);
#else
  const htri_t is_hdf5 = H5Fis_hdf5(path.c_str());
#endif
  if (is_hdf5 <= 0) throw InputError(open_err + "not an HDF5 file");
  im.file = Must(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, open_err,
                 "damaged or truncated HDF5 file");

  // Header.
  header_.tactip_version = im.RootString("tactip_version");
  header_.scenario = im.RootString("scenario");
  header_.seed = im.RootUint64("seed");
  header_.config_yaml = im.RootString("config_yaml");
  header_.shard = im.RootShard();

  // Runs: children of /runs named run_NNNN, ascending.
  if (H5Lexists(im.file.get(), "runs", H5P_DEFAULT) <= 0) throw InputError(im.Name() + " has no group /runs");
  const hid_t gid = H5Gopen2(im.file.get(), "runs", H5P_DEFAULT);
  if (gid < 0) throw InputError(im.Name() + " has no group /runs");
  im.runs = Hid(gid, H5Gclose);
  H5G_info_t info;
  MustOk(H5Gget_info(im.runs.get(), &info), im.err, "cannot list /runs");
  for (hsize_t i = 0; i < info.nlinks; ++i) {
    const ssize_t len =
        H5Lget_name_by_idx(im.runs.get(), ".", H5_INDEX_NAME, H5_ITER_INC, i, nullptr, 0, H5P_DEFAULT);
    if (len < 0) Fail(im.err, "cannot list /runs");
    std::string name(static_cast<size_t>(len) + 1, '\0');
    if (H5Lget_name_by_idx(im.runs.get(), ".", H5_INDEX_NAME, H5_ITER_INC, i, name.data(), name.size(),
                           H5P_DEFAULT) < 0) {
      Fail(im.err, "cannot list /runs");
    }
    name.resize(static_cast<size_t>(len));
    const int index = ParseRunName(name);
    if (index < 0) {
      throw InputError(im.Name() + ": /runs/" + name + " is not a run (runs are named run_NNNN, NNNN from 0000 to " +
                       std::to_string(std::numeric_limits<int>::max()) + ")");
    }
    runs_.push_back(index);
  }
  if (runs_.empty()) throw InputError(im.Name() + " has no runs (/runs is empty)");
  std::sort(runs_.begin(), runs_.end());
}

DatasetReader::~DatasetReader() = default;

RunRecord DatasetReader::ReadRun(int index) const {
  const QuietHdf5 quiet;
  const Impl& im = *impl_;
  const Hid group = im.OpenRun(index, runs_);
  const hid_t g = group.get();
  const std::string name = RunGroupName(index);
  RunRecord run = im.ReadSummary(g, index);
  const hsize_t t = run.frames();
  const hsize_t n = static_cast<hsize_t>(run.n_pins);
  run.pos_px = im.ReadArray<float>(g, name, "pins/pos_px", {t, n, 2});
  run.valid = im.ReadArray<std::uint8_t>(g, name, "pins/valid", {t, n});
  run.pos_m = im.ReadArray<float>(g, name, "pins/pos_m", {t, n, 3});
  run.gross_slip = im.ReadArray<std::uint8_t>(g, name, "labels/gross_slip", {t});
  run.pin_slip = im.ReadArray<std::uint8_t>(g, name, "labels/pin_slip", {t, n});
  run.pin_contact = im.ReadArray<std::uint8_t>(g, name, "labels/pin_contact", {t, n});
  run.normal_N = im.ReadArray<float>(g, name, "contact/normal_N", {t, n});
  run.tangential_N = im.ReadArray<float>(g, name, "contact/tangential_N", {t, n, 2});
  run.object_height_m = im.ReadArray<double>(g, name, "object/height_m", {t});
  // Optional arrays: partial-slip labels (absent in files from before they existed; then
  // derived from the per-pin labels) and the external camera (transparent rigs only).
  if (Impl::HasArray(g, "labels/incipient")) {
    run.incipient = im.ReadArray<std::uint8_t>(g, name, "labels/incipient", {t});
  } else {
    run.incipient = PartialSlipLabels(run.pin_contact, run.pin_slip, run.n_pins);
  }
  if (Impl::HasArray(g, "external/pos_px")) {
    run.external_px = im.ReadArray<float>(g, name, "external/pos_px", {t, n, 2});
    run.external_m = im.ReadArray<float>(g, name, "external/pos_m", {t, n, 3});
  }
  CheckRunValues(run, im.Name());
  return run;
}

RunRecord DatasetReader::ReadRunSummary(int index) const {
  const QuietHdf5 quiet;
  const Impl& im = *impl_;
  const Hid group = im.OpenRun(index, runs_);
  return im.ReadSummary(group.get(), index);
}

}  // namespace tactip
