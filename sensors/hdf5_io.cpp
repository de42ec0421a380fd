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

Hid CreateGroup(hid_t parent, const char* name, const std::string& where, WriteErrors& err) {
  const Hid gcpl = UntimedGroupProps(err);
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

}  // namespace tactip::hdf5
