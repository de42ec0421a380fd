#include "sensors/run_group_reader.h"

#include <cstdint>
#include <limits>

#include <fmt/format.h>

#include "sensors/image_hdf5.h"
#include "sensors/run_checks.h"
#include "sim/config.h"

namespace tactip {

using namespace hdf5;

RunGroupReader::RunGroupReader(hid_t group, int index, int layout_version, const std::string& path)
    : group_(group),
      index_(index),
      layout_(layout_version),
      run_(RunGroupName(index)),
      path_(path),
      err_("cannot read dataset '" + path + "': ") {}

std::string RunGroupReader::Name() const { return "dataset '" + path_ + "'"; }

bool RunGroupReader::HasLink(const std::string& rel) const {
  size_t slash = 0;
  // Every link on the path must exist (H5Lexists fails on a missing parent).
  while ((slash = rel.find('/', slash + 1)) != std::string::npos) {
    if (H5Lexists(group_, rel.substr(0, slash).c_str(), H5P_DEFAULT) <= 0) return false;
  }
  return H5Lexists(group_, rel.c_str(), H5P_DEFAULT) > 0;
}

Hid RunGroupReader::OpenArray(const std::string& rel) const {
  const hid_t id = H5Dopen2(group_, rel.c_str(), H5P_DEFAULT);
  if (id < 0) throw InputError(Name() + ": " + run_ + " has no array " + rel);
  return Hid(id, H5Dclose);
}

std::vector<hsize_t> RunGroupReader::ShapeOf(const std::string& rel) const {
  const std::string what = "cannot read /runs/" + run_ + "/" + rel;
  const Hid dset = OpenArray(rel);
  const Hid space = Must(H5Dget_space(dset.get()), H5Sclose, err_, what);
  const int rank = H5Sget_simple_extent_ndims(space.get());
  if (rank < 0) Fail(err_, what);
  std::vector<hsize_t> shape(static_cast<size_t>(rank));
  MustOk(H5Sget_simple_extent_dims(space.get(), shape.data(), nullptr), err_, what);
  return shape;
}

template <class T>
std::vector<T> RunGroupReader::ReadArray(const std::string& rel, const std::vector<hsize_t>& expected) const {
  const std::string what = "cannot read /runs/" + run_ + "/" + rel;
  const std::vector<hsize_t> shape = ShapeOf(rel);
  if (shape != expected) {
    throw InputError(Name() + ": " + run_ + "/" + rel + " has shape " + ShapeText(shape) + ", expected " +
                     ShapeText(expected));
  }
  size_t count = 1;
  for (hsize_t d : shape) count *= static_cast<size_t>(d);
  std::vector<T> out(count);
  if (count > 0) {
    const Hid dset = OpenArray(rel);
    MustOk(H5Dread(dset.get(), H5Types<T>::mem(), H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()), err_, what);
  }
  return out;
}

void RunGroupReader::ReadAttrs(hid_t obj, const std::string& rel, std::map<std::string, double>& attrs,
                               std::map<std::string, std::string>& text) const {
  const std::string what = "cannot read attributes of /runs/" + run_ + rel;
  // Every scalar attribute: numbers as double, strings as text; others are ignored.
  for (const std::string& key : AttrNames(obj, err_, what)) {
    const Hid attr = Must(H5Aopen(obj, key.c_str(), H5P_DEFAULT), H5Aclose, err_, what);
    switch (KindOf(attr.get(), err_, what)) {
      case AttrKind::kNumber: {
        double value = 0.0;
        MustOk(H5Aread(attr.get(), H5T_NATIVE_DOUBLE, &value), err_, what);
        attrs[key] = value;
        break;
      }
      case AttrKind::kString:
        text[key] = ReadStringAttr(attr.get(), err_, what);
        break;
      case AttrKind::kOther:
        break;
    }
  }
}

void RunGroupReader::ReadRunAttrs(RunRecord& run) const {
  ReadAttrs(group_, "", run.attrs, run.text_attrs);
  if (layout_ < 2 || !HasLink("events")) return;
  // Layout 2: the event times from events/, into the run's attributes as layout 1 has them.
  const Hid events = Must(H5Gopen2(group_, "events", H5P_DEFAULT), H5Gclose, err_, "cannot open " + run_ + "/events");
  std::map<std::string, double> times;
  std::map<std::string, std::string> text;
  ReadAttrs(events.get(), "/events", times, text);
  for (const auto& [key, value] : times) {
    if (run.attrs.count(key) != 0 || run.text_attrs.count(key) != 0) {
      throw InputError(Name() + ": " + run_ + " has attribute '" + key + "' both on the run and in events/");
    }
    run.attrs[key] = value;
  }
}

void RunGroupReader::ReadTime(RunRecord& run) const {
  const std::vector<hsize_t> shape = ShapeOf("time");
  if (shape.size() != 1) {
    throw InputError(Name() + ": " + run_ + "/time has shape " + ShapeText(shape) + ", expected (T)");
  }
  run.time = ReadArray<double>("time", shape);
}

std::vector<std::string> RunGroupReader::SensorGroupNames() const {
  if (layout_ < 2) return {"tactip"};  // layout 1: one sensor, its arrays under the run
  if (!HasLink("sensors")) throw InputError(Name() + ": " + run_ + " has no group sensors");
  const std::string what = "cannot list /runs/" + run_ + "/sensors";
  const Hid sensors = Must(H5Gopen2(group_, "sensors", H5P_DEFAULT), H5Gclose, err_, what);
  std::vector<std::string> names = MemberNames(sensors.get(), err_, what);
  if (names.empty()) throw InputError(Name() + ": " + run_ + "/sensors holds no sensor (a run needs at least one)");
  return names;
}

SensorRecord RunGroupReader::ReadSensorSummary(const std::string& name, hsize_t t) const {
  SensorRecord s;
  s.name = name;
  const std::string at = SensorPath(layout_, name);
  // N from pins/valid (T, N); only its shape is read.
  const std::vector<hsize_t> shape = ShapeOf(at + "pins/valid");
  if (shape.size() != 2 || shape[0] != t || shape[1] < 1 ||
      shape[1] > static_cast<hsize_t>(std::numeric_limits<int>::max())) {
    throw InputError(Name() + ": " + run_ + "/" + at + "pins/valid has shape " + ShapeText(shape) + ", expected (" +
                     std::to_string(t) + ", N)");
  }
  s.n_pins = static_cast<int>(shape[1]);
  if (layout_ < 2) return s;
  // Layout 2: the sensor group's attributes; n_pins must agree with the arrays.
  const std::string rel = "sensors/" + name;
  const Hid group = Must(H5Gopen2(group_, rel.c_str(), H5P_DEFAULT), H5Gclose, err_, "cannot open " + run_ + "/" + rel);
  ReadAttrs(group.get(), "/" + rel, s.attrs, s.text_attrs);
  const auto n_pins = s.attrs.find("n_pins");
  if (n_pins != s.attrs.end()) {
    if (n_pins->second != s.n_pins) {
      throw InputError(Name() + ": " + run_ + "/" + rel + " has n_pins = " + fmt::format("{}", n_pins->second) +
                       " but its pins/valid holds " + std::to_string(s.n_pins) + " pins");
    }
    s.attrs.erase(n_pins);
  }
  return s;
}

void RunGroupReader::ReadSensorArrays(SensorRecord& s, hsize_t t) const {
  const std::string at = SensorPath(layout_, s.name);
  const hsize_t n = static_cast<hsize_t>(s.n_pins);
  s.pos_px = ReadArray<float>(at + "pins/pos_px", {t, n, 2});
  s.valid = ReadArray<std::uint8_t>(at + "pins/valid", {t, n});
  s.pos_m = ReadArray<float>(at + "pins/pos_m", {t, n, 3});
  s.gross_slip = ReadArray<std::uint8_t>(at + "labels/gross_slip", {t});
  s.pin_slip = ReadArray<std::uint8_t>(at + "labels/pin_slip", {t, n});
  s.pin_contact = ReadArray<std::uint8_t>(at + "labels/pin_contact", {t, n});
  s.normal_N = ReadArray<float>(at + "contact/normal_N", {t, n});
  s.tangential_N = ReadArray<float>(at + "contact/tangential_N", {t, n, 2});
  // Optional arrays: partial-slip labels (absent in files from before they existed; then
  // derived from the per-pin labels), the pins' first slips and the external camera
  // (transparent rigs only).
  if (HasLink(at + "labels/incipient")) {
    s.incipient = ReadArray<std::uint8_t>(at + "labels/incipient", {t});
  } else {
    s.incipient = PartialSlipLabels(s.pin_contact, s.pin_slip, s.n_pins);
  }
  if (HasLink(at + "labels/pin_first_slip_s")) {
    s.pin_first_slip_s = ReadArray<double>(at + "labels/pin_first_slip_s", {n});
  }
  if (HasLink(at + "external/pos_px")) {
    s.external_px = ReadArray<float>(at + "external/pos_px", {t, n, 2});
    s.external_m = ReadArray<float>(at + "external/pos_m", {t, n, 3});
  }
  // Optional: the rendered frames and the blob pipeline's pins (images.enabled).
  if (HasLink(at + "images")) {
    ImageStack stack = ReadImageArray(OpenArray(at + "images").get(), t, Name() + ": ", run_ + "/" + at + "images");
    s.images = std::move(stack.frames);
    s.image_width = stack.width;
    s.image_height = stack.height;
    s.detected_px = ReadArray<float>(at + "pins/detected_px", {t, n, 2});
    s.detected_valid = ReadArray<std::uint8_t>(at + "pins/detected_valid", {t, n});
  }
}

ActionRecord RunGroupReader::ReadActions(hsize_t t) const {
  ActionRecord actions;
  if (layout_ < 2 || !HasLink("actions")) return actions;  // layout 1 records no controller
  // Controls (T, U) with their U actuator names.
  if (HasLink("actions/controls")) {
    const std::vector<hsize_t> shape = ShapeOf("actions/controls");
    if (shape.size() != 2 || shape[0] != t || shape[1] < 1) {
      throw InputError(Name() + ": " + run_ + "/actions/controls has shape " + ShapeText(shape) + ", expected (" +
                       std::to_string(t) + ", U)");
    }
    actions.controls = ReadArray<double>("actions/controls", shape);
    const Hid dset = OpenArray("actions/controls");
    const std::string where = run_ + "/actions/controls attribute 'actuators'";
    if (H5Aexists(dset.get(), "actuators") <= 0) {
      throw InputError(Name() + ": " + run_ + "/actions/controls has no attribute 'actuators'");
    }
    const Hid attr = Must(H5Aopen(dset.get(), "actuators", H5P_DEFAULT), H5Aclose, err_, "cannot open " + where);
    actions.actuators = ReadStringList(attr.get(), true, Name() + ": ", where);
    if (actions.actuators.size() != shape[1]) {
      throw InputError(Name() + ": " + where + " names " + std::to_string(actions.actuators.size()) +
                       " actuators for " + std::to_string(shape[1]) + " columns of controls");
    }
  }
  // What the controller did (A), and when.
  const std::vector<hsize_t> shape = ShapeOf("actions/time");
  if (shape.size() != 1) {
    throw InputError(Name() + ": " + run_ + "/actions/time has shape " + ShapeText(shape) + ", expected (A)");
  }
  const std::vector<double> time = ReadArray<double>("actions/time", shape);
  const Hid what = OpenArray("actions/what");
  const std::vector<std::string> text = ReadStringList(what.get(), false, Name() + ": ", run_ + "/actions/what");
  if (text.size() != time.size()) {
    throw InputError(Name() + ": " + run_ + "/actions/what has " + std::to_string(text.size()) +
                     " entries, actions/time " + std::to_string(time.size()));
  }
  for (size_t k = 0; k < time.size(); ++k) actions.list.push_back({time[k], text[k]});
  return actions;
}

RunRecord RunGroupReader::Summary() const {
  RunRecord run;
  run.index = index_;
  ReadRunAttrs(run);
  ReadTime(run);
  for (const std::string& name : SensorGroupNames()) run.sensors.push_back(ReadSensorSummary(name, run.frames()));
  if (layout_ < 2) {
    // Layout 1 keeps the sensor's attributes (skin_pattern) among the run's.
    for (auto it = run.text_attrs.begin(); it != run.text_attrs.end();) {
      if (!IsSensorAttribute(it->first)) {
        ++it;
        continue;
      }
      run.sensors.front().text_attrs.insert(*it);
      it = run.text_attrs.erase(it);
    }
  }
  CheckRunTimes(run, Name());
  return run;
}

RunRecord RunGroupReader::Full() const {
  RunRecord run = Summary();
  const hsize_t t = run.frames();
  for (SensorRecord& s : run.sensors) ReadSensorArrays(s, t);
  run.object_height_m = ReadArray<double>("object/height_m", {t});
  run.actions = ReadActions(t);
  CheckRunValues(run, Name(), layout_);
  return run;
}

}  // namespace tactip
