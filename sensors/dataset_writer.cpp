#include "sensors/dataset.h"

#include <fcntl.h>
#include <hdf5.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <stdexcept>

#include "sensors/hdf5_discard.h"
#include "sensors/hdf5_io.h"
#include "sim/config.h"
#include "sim/files.h"

namespace tactip {
namespace {

using namespace hdf5;

/// Bytes that must be free when a file is created: more than H5Fcreate writes.
constexpr long long kHeaderRoom = 16 * 1024;

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

}  // namespace

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

}  // namespace tactip
