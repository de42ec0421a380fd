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
#include "sensors/run_group_reader.h"
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

  /// Reads the optional root attribute `layout_version` (1 when absent), which must be a
  /// layout this reader knows.
  int RootLayout() const {
    if (H5Aexists(file.get(), "layout_version") <= 0) return 1;
    const std::uint64_t layout = RootUint64("layout_version");
    if (layout < 1 || layout > static_cast<std::uint64_t>(kDatasetLayoutVersion)) {
      throw InputError(Name() + ": root attribute 'layout_version' = " + std::to_string(layout) +
                       " is not a layout this tactip reads (1 to " + std::to_string(kDatasetLayoutVersion) + ")");
    }
    return static_cast<int>(layout);
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
  header_.layout_version = im.RootLayout();

  // Runs: children of /runs named run_NNNN, ascending.
  if (H5Lexists(im.file.get(), "runs", H5P_DEFAULT) <= 0) throw InputError(im.Name() + " has no group /runs");
  const hid_t gid = H5Gopen2(im.file.get(), "runs", H5P_DEFAULT);
  if (gid < 0) throw InputError(im.Name() + " has no group /runs");
  im.runs = Hid(gid, H5Gclose);
  for (const std::string& name : MemberNames(im.runs.get(), im.err, "cannot list /runs")) {
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
  const Hid group = impl_->OpenRun(index, runs_);
  return RunGroupReader(group.get(), index, header_.layout_version, impl_->path).Full();
}

RunRecord DatasetReader::ReadRunSummary(int index) const {
  const QuietHdf5 quiet;
  const Hid group = impl_->OpenRun(index, runs_);
  return RunGroupReader(group.get(), index, header_.layout_version, impl_->path).Summary();
}

}  // namespace tactip
