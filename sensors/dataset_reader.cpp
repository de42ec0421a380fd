#include "sensors/dataset.h"

#include <fcntl.h>
#include <hdf5.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <filesystem>
#include <limits>
#include <memory>
#include <string_view>

#include "sensors/hdf5_io.h"
#include "sensors/run_checks.h"
#include "sim/config.h"

namespace tactip {
namespace {

using namespace hdf5;

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


}  // namespace

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
