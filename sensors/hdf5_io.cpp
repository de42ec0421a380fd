#include "sensors/hdf5_io.h"

#include <algorithm>
#include <cstring>
#include <memory>
#include <string_view>

#include "sensors/hdf5_discard.h"
#include "sim/config.h"

namespace tactip::hdf5 {

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

std::string FailureMessage(const std::string& prefix, const std::string& what) {
  const std::string detail = Hdf5Detail();
  return prefix + what + (detail.empty() ? "" : " (" + detail + ")");
}

void Fail(const std::string& prefix, const std::string& what) {
  throw InputError(FailureMessage(prefix, what));
}

Hid Must(hid_t id, Hid::Closer close, const std::string& prefix, const std::string& what) {
  if (id < 0) Fail(prefix, what);
  return Hid(id, close);
}

void MustOk(herr_t status, const std::string& prefix, const std::string& what) {
  if (status < 0) Fail(prefix, what);
}

void WriteErrors::Fail(const std::string& what) {
  const std::string message = FailureMessage(prefix, what);  // before HDF5's error stack changes
  failed = true;
  DiscardPendingWrites(file);
  throw InputError(message);
}

Hid Must(hid_t id, Hid::Closer close, WriteErrors& err, const std::string& what) {
  if (id < 0) err.Fail(what);
  return Hid(id, close);
}

void MustOk(herr_t status, WriteErrors& err, const std::string& what) {
  if (status < 0) err.Fail(what);
}

Hid Utf8StringType(WriteErrors& err) {
  Hid type = Must(H5Tcopy(H5T_C_S1), H5Tclose, err, "cannot create string type");
  MustOk(H5Tset_size(type.get(), H5T_VARIABLE), err, "cannot create string type");
  MustOk(H5Tset_cset(type.get(), H5T_CSET_UTF8), err, "cannot create string type");
  return type;
}

Hid UntimedGroupProps(WriteErrors& err) {
  Hid gcpl = Must(H5Pcreate(H5P_GROUP_CREATE), H5Pclose, err, "cannot create group properties");
  MustOk(H5Pset_obj_track_times(gcpl.get(), 0), err, "cannot disable group times");
  return gcpl;
}

Hid CreateGroup(hid_t parent, const char* name, const std::string& where, WriteErrors& err, bool ordered) {
  const Hid gcpl = UntimedGroupProps(err);
  if (ordered) {
    MustOk(H5Pset_link_creation_order(gcpl.get(), H5P_CRT_ORDER_TRACKED | H5P_CRT_ORDER_INDEXED), err,
           "cannot create group " + where);
  }
  return Must(H5Gcreate2(parent, name, H5P_DEFAULT, gcpl.get(), H5P_DEFAULT), H5Gclose, err,
              "cannot create group " + where);
}

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

void WriteScalarAttr(hid_t obj, const std::string& name, hid_t file_type, hid_t mem_type, const void* value,
                     const std::string& where, WriteErrors& err) {
  const std::string what = "cannot write attribute '" + name + "' of " + where;
  const Hid space = Must(H5Screate(H5S_SCALAR), H5Sclose, err, what);
  const Hid attr =
      Must(H5Acreate2(obj, name.c_str(), file_type, space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose, err, what);
  MustOk(H5Awrite(attr.get(), mem_type, value), err, what);
}


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

std::string ShapeText(const std::vector<hsize_t>& shape) {
  std::string out = "(";
  for (size_t i = 0; i < shape.size(); ++i) out += (i ? ", " : "") + std::to_string(shape[i]);
  return out + ")";
}

namespace {

/// The variable-length strings `values` as the C pointers HDF5 writes.
std::vector<const char*> CStrings(const std::vector<std::string>& values) {
  std::vector<const char*> out;
  out.reserve(values.size());
  for (const std::string& v : values) out.push_back(v.c_str());
  return out;
}

/// Frees the strings HDF5 allocated while reading variable-length strings.
class VlenStrings {
 public:
  VlenStrings(size_t count, hid_t mem_type, hid_t space) : text_(count, nullptr), type_(mem_type), space_(space) {}
  ~VlenStrings() {
#if H5_VERSION_GE(1, 12, 0)
    H5Treclaim(type_, space_, H5P_DEFAULT, text_.data());
#else
    H5Dvlen_reclaim(type_, space_, H5P_DEFAULT, text_.data());
#endif
  }
  VlenStrings(const VlenStrings&) = delete;
  VlenStrings& operator=(const VlenStrings&) = delete;
  char** data() { return text_.data(); }
  std::vector<std::string> Strings() const {
    std::vector<std::string> out;
    for (const char* t : text_) out.emplace_back(t != nullptr ? t : "");
    return out;
  }

 private:
  std::vector<char*> text_;
  hid_t type_, space_;
};

}  // namespace

void WriteStringListAttr(hid_t obj, const std::string& name, const std::vector<std::string>& values,
                         const std::string& where, WriteErrors& err) {
  const std::string what = "cannot write attribute '" + name + "' of " + where;
  const Hid type = Utf8StringType(err);
  const hsize_t dims[1] = {values.size()};
  const Hid space = Must(H5Screate_simple(1, dims, nullptr), H5Sclose, err, what);
  const Hid attr = Must(H5Acreate2(obj, name.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose,
                        err, what);
  if (values.empty()) return;
  const std::vector<const char*> text = CStrings(values);
  MustOk(H5Awrite(attr.get(), type.get(), text.data()), err, what);
}

void WriteStringArray(hid_t parent, const char* name, const std::vector<std::string>& values,
                      const std::string& where, WriteErrors& err) {
  const std::string path = where + "/" + name;
  const Hid type = Utf8StringType(err);
  const hsize_t dims[1] = {values.size()};
  const Hid space = Must(H5Screate_simple(1, dims, nullptr), H5Sclose, err, "cannot create " + path);
  const Hid dcpl = Must(H5Pcreate(H5P_DATASET_CREATE), H5Pclose, err, "cannot create " + path);
  MustOk(H5Pset_obj_track_times(dcpl.get(), 0), err, "cannot create " + path);
  const Hid dset = Must(H5Dcreate2(parent, name, type.get(), space.get(), H5P_DEFAULT, dcpl.get(), H5P_DEFAULT),
                        H5Dclose, err, "cannot create " + path);
  if (values.empty()) return;
  const std::vector<const char*> text = CStrings(values);
  MustOk(H5Dwrite(dset.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, text.data()), err, "cannot write " + path);
}

std::vector<std::string> ReadStringList(hid_t obj, bool is_attr, const std::string& err, const std::string& where) {
  const std::string what = "cannot read " + where;
  const Hid file_type = Must(is_attr ? H5Aget_type(obj) : H5Dget_type(obj), H5Tclose, err, what);
  const Hid space = Must(is_attr ? H5Aget_space(obj) : H5Dget_space(obj), H5Sclose, err, what);
  const int rank = H5Sget_simple_extent_ndims(space.get());
  if (H5Tget_class(file_type.get()) != H5T_STRING || H5Tis_variable_str(file_type.get()) <= 0 || rank > 1) {
    throw InputError(err + where + " is not a list of strings");
  }
  const hssize_t count = H5Sget_simple_extent_npoints(space.get());
  if (count < 0) Fail(err, what);
  if (count == 0) return {};
  // Variable length: HDF5 allocates each text; VlenStrings releases them.
  const Hid mem_type = Must(H5Tcopy(H5T_C_S1), H5Tclose, err, what);
  MustOk(H5Tset_size(mem_type.get(), H5T_VARIABLE), err, what);
  MustOk(H5Tset_cset(mem_type.get(), H5Tget_cset(file_type.get())), err, what);
  VlenStrings text(static_cast<size_t>(count), mem_type.get(), space.get());
  MustOk(is_attr ? H5Aread(obj, mem_type.get(), text.data())
                 : H5Dread(obj, mem_type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, text.data()),
         err, what);
  return text.Strings();
}

std::vector<std::string> MemberNames(hid_t group, const std::string& err, const std::string& what) {
  // Creation order when the group tracks it (sensors are listed as written).
  const Hid gcpl = Must(H5Gget_create_plist(group), H5Pclose, err, what);
  unsigned order = 0;
  MustOk(H5Pget_link_creation_order(gcpl.get(), &order), err, what);
  const H5_index_t index = (order & H5P_CRT_ORDER_INDEXED) != 0 ? H5_INDEX_CRT_ORDER : H5_INDEX_NAME;
  H5G_info_t info;
  MustOk(H5Gget_info(group, &info), err, what);
  std::vector<std::string> names;
  for (hsize_t i = 0; i < info.nlinks; ++i) {
    const ssize_t len = H5Lget_name_by_idx(group, ".", index, H5_ITER_INC, i, nullptr, 0, H5P_DEFAULT);
    if (len < 0) Fail(err, what);
    std::string name(static_cast<size_t>(len) + 1, '\0');
    if (H5Lget_name_by_idx(group, ".", index, H5_ITER_INC, i, name.data(), name.size(), H5P_DEFAULT) < 0) {
      Fail(err, what);
    }
    name.resize(static_cast<size_t>(len));
    names.push_back(std::move(name));
  }
  return names;
}

}  // namespace tactip::hdf5
