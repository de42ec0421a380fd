#include "sensors/dataset.h"

#include <fcntl.h>
#include <hdf5.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>
#include <memory>
#include <stdexcept>

#include "sensors/hdf5_discard.h"
#include "sensors/hdf5_io.h"
#include "sensors/image_hdf5.h"
#include "sim/config.h"
#include "sim/base/files.h"

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

/// Index of the first infinite value of `v` (NaN allowed), -1 if none.
long long FirstInfinite(const std::vector<double>& v) {
  for (size_t k = 0; k < v.size(); ++k) {
    if (std::isinf(v[k])) return static_cast<long long>(k);
  }
  return -1;
}

/// An array that must hold finite values: its path in the run, the index of its first
/// non-finite value (-1: none), values per frame and per pin (0: no pin axis), and what its
/// first axis counts.
struct FiniteCheck {
  std::string path;
  long long bad;
  size_t per_frame, per_pin;
  const char* counts = "frame";
};

/// The arrays of `run` that must be finite, with their paths in the file.
std::vector<FiniteCheck> FiniteChecks(const RunRecord& run) {
  std::vector<FiniteCheck> out = {{"time", FirstNonFinite(run.time), 1, 0}};
  for (const SensorRecord& s : run.sensors) {
    const std::string at = SensorPath(kDatasetLayoutVersion, s.name);
    const size_t n = static_cast<size_t>(s.n_pins);
    out.push_back({at + "pins/pos_px", FirstNonFinite(s.pos_px), 2 * n, 2});
    out.push_back({at + "pins/pos_m", FirstNonFinite(s.pos_m), 3 * n, 3});
    out.push_back({at + "pins/detected_px", FirstNonFinite(s.detected_px), 2 * n, 2});
    out.push_back({at + "external/pos_px", FirstNonFinite(s.external_px), 2 * n, 2});
    out.push_back({at + "external/pos_m", FirstNonFinite(s.external_m), 3 * n, 3});
    out.push_back({at + "contact/normal_N", FirstNonFinite(s.normal_N), n, 1});
    out.push_back({at + "contact/tangential_N", FirstNonFinite(s.tangential_N), 2 * n, 2});
    out.push_back({at + "labels/pin_first_slip_s", FirstInfinite(s.pin_first_slip_s), 1, 0, "pin"});  // NaN: never
  }
  out.push_back({"object/height_m", FirstNonFinite(run.object_height_m), 1, 0});
  out.push_back({"actions/controls", FirstNonFinite(run.actions.controls), run.actions.actuators.size(), 0});
  std::vector<double> action_times;
  for (const ControllerAction& a : run.actions.list) action_times.push_back(a.time_s);
  out.push_back({"actions/time", FirstNonFinite(action_times), 1, 0, "action"});
  return out;
}

/// Throws InputError (prefix `err`) naming the first array of `run` that holds a non-finite
/// value, with its frame and pin: such a value is no data, and a file must not carry it.
void CheckFinite(const RunRecord& run, const std::string& err) {
  for (const FiniteCheck& a : FiniteChecks(run)) {
    if (a.bad < 0) continue;
    const size_t k = static_cast<size_t>(a.bad);
    std::string where = std::string(a.counts) + " " + std::to_string(k / a.per_frame);
    if (a.per_pin > 0) where += ", pin " + std::to_string((k % a.per_frame) / a.per_pin);
    throw InputError(err + "/runs/" + RunGroupName(run.index) + "/" + a.path + " would hold a non-finite value (" +
                     where + "); the run is not written");
  }
}

/// Writes numeric attributes `attrs` (those `pick` selects) then text attributes `text` on
/// `obj` (path `where`), each in name order.
void WriteAttrs(hid_t obj, const std::map<std::string, double>& attrs, bool (*pick)(const std::string&),
                const std::map<std::string, std::string>& text, const std::string& where, WriteErrors& err) {
  for (const auto& [key, value] : attrs) {
    if (pick(key)) WriteScalarAttr(obj, key, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &value, where, err);
  }
  for (const auto& [key, value] : text) WriteStringAttr(obj, key, value, where, err);
}

/// Writes sensor `s` of a T-frame run as group `s.name` under `sensors` (path `where`).
void WriteSensor(hid_t sensors, const SensorRecord& s, hsize_t t, const std::string& where, WriteErrors& err) {
  const std::string at = where + "/" + s.name;
  const Hid group = CreateGroup(sensors, s.name.c_str(), at, err);
  const hid_t g = group.get();
  const std::int64_t n_pins = s.n_pins;
  WriteScalarAttr(g, "n_pins", H5T_STD_I64LE, H5T_NATIVE_INT64, &n_pins, at, err);
  WriteAttrs(g, s.attrs, [](const std::string&) { return true; }, s.text_attrs, at, err);
  const hsize_t n = static_cast<hsize_t>(s.n_pins);
  {
    const Hid pins = CreateGroup(g, "pins", at + "/pins", err);
    WriteArray(pins.get(), "pos_px", {t, n, 2}, s.pos_px, "px", at + "/pins", err);
    WriteArray(pins.get(), "valid", {t, n}, s.valid, "1", at + "/pins", err);
    WriteArray(pins.get(), "pos_m", {t, n, 3}, s.pos_m, "m", at + "/pins", err);
    if (!s.images.empty()) {
      // The blob pipeline's pins, beside the camera model's.
      WriteArray(pins.get(), "detected_px", {t, n, 2}, s.detected_px, "px", at + "/pins", err);
      WriteArray(pins.get(), "detected_valid", {t, n}, s.detected_valid, "1", at + "/pins", err);
    }
  }
  if (!s.images.empty()) WriteImageArray(g, "images", s.images, s.image_width, s.image_height, at, err);
  {
    const Hid labels = CreateGroup(g, "labels", at + "/labels", err);
    WriteArray(labels.get(), "gross_slip", {t}, s.gross_slip, "1", at + "/labels", err);
    WriteArray(labels.get(), "pin_slip", {t, n}, s.pin_slip, "1", at + "/labels", err);
    WriteArray(labels.get(), "pin_contact", {t, n}, s.pin_contact, "1", at + "/labels", err);
    WriteArray(labels.get(), "incipient", {t}, s.incipient, "1", at + "/labels", err);
    if (!s.pin_first_slip_s.empty()) {
      WriteArray(labels.get(), "pin_first_slip_s", {n}, s.pin_first_slip_s, "s", at + "/labels", err);
    }
  }
  if (!s.external_px.empty()) {
    const Hid ext = CreateGroup(g, "external", at + "/external", err);
    WriteArray(ext.get(), "pos_px", {t, n, 2}, s.external_px, "px", at + "/external", err);
    WriteArray(ext.get(), "pos_m", {t, n, 3}, s.external_m, "m", at + "/external", err);
  }
  const Hid contact = CreateGroup(g, "contact", at + "/contact", err);
  WriteArray(contact.get(), "normal_N", {t, n}, s.normal_N, "N", at + "/contact", err);
  WriteArray(contact.get(), "tangential_N", {t, n, 2}, s.tangential_N, "N", at + "/contact", err);
}

/// Writes group actions/ of a T-frame run under `run` (path `where`): the controls with
/// their actuators' names, and what the controller did when.
void WriteActions(hid_t run, const ActionRecord& actions, hsize_t t, const std::string& where, WriteErrors& err) {
  const std::string at = where + "/actions";
  const Hid group = CreateGroup(run, "actions", at, err);
  if (!actions.actuators.empty()) {
    WriteArray(group.get(), "controls", {t, actions.actuators.size()}, actions.controls, "ctrl", at, err);
    const Hid controls = Must(H5Dopen2(group.get(), "controls", H5P_DEFAULT), H5Dclose, err, "cannot open " + at);
    WriteStringListAttr(controls.get(), "actuators", actions.actuators, at + "/controls", err);
  }
  std::vector<double> time;
  std::vector<std::string> what;
  for (const ControllerAction& a : actions.list) {
    time.push_back(a.time_s);
    what.push_back(a.what);
  }
  WriteArray(group.get(), "time", {time.size()}, time, "s", at, err);
  WriteStringArray(group.get(), "what", what, at, err);
}

/// Writes the groups and attributes of `run` into its (new, empty) group `g` (path `where`).
void WriteRunContents(hid_t g, const RunRecord& run, const std::string& where, WriteErrors& err) {
  // Run attributes other than the events, in name order, numeric then text.
  WriteAttrs(g, run.attrs, [](const std::string& k) { return !IsEventAttribute(k); }, run.text_attrs, where, err);
  const hsize_t t = run.frames();
  WriteArray(g, "time", {t}, run.time, "s", where, err);
  {
    // Sensors in the record's (scene) order.
    const Hid sensors = CreateGroup(g, "sensors", where + "/sensors", err, /*ordered=*/true);
    for (const SensorRecord& s : run.sensors) WriteSensor(sensors.get(), s, t, where + "/sensors", err);
  }
  {
    const Hid object = CreateGroup(g, "object", where + "/object", err);
    WriteArray(object.get(), "height_m", {t}, run.object_height_m, "m", where + "/object", err);
  }
  {
    const Hid events = CreateGroup(g, "events", where + "/events", err);
    WriteAttrs(events.get(), run.attrs, IsEventAttribute, {}, where + "/events", err);
  }
  if (!run.actions.empty()) WriteActions(g, run.actions, t, where, err);
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
  const std::uint64_t layout = kDatasetLayoutVersion;
  WriteScalarAttr(root, "layout_version", H5T_STD_U64LE, H5T_NATIVE_UINT64, &layout, "/", im.err);
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
  const QuietHdf5 quiet;
  Impl& im = *impl_;
  const std::string name = RunGroupName(run.index);
  const std::string where = "/runs/" + name;
  if (H5Lexists(im.runs.get(), name.c_str(), H5P_DEFAULT) > 0) {
    throw std::logic_error("DatasetWriter: " + name + " written twice to '" + path_ + "'");
  }

  try {
    const Hid group = CreateGroup(im.runs.get(), name.c_str(), where, im.err);
    WriteRunContents(group.get(), run, where, im.err);
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
