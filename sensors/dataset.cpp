#include "sensors/dataset.h"

#include <algorithm>
#include <cstdio>
#include <iterator>
#include <stdexcept>

namespace tactip {

namespace {

/// Throws std::invalid_argument(who + field ...) unless `actual` == `expected` values.
void CheckCount(const std::string& who, const char* field, size_t actual, size_t expected, const char* shape,
                const std::string& dims) {
  if (actual != expected) {
    throw std::invalid_argument(who + field + " has " + std::to_string(actual) + " values, expected " +
                           std::to_string(expected) + " = " + shape + dims);
  }
}

/// Throws std::logic_error unless `actions` fits T = `t` frames.
void CheckActions(const ActionRecord& actions, size_t t, const std::string& who) {
  const size_t u = actions.actuators.size();
  for (size_t k = 0; k < u; ++k) {
    const std::string& name = actions.actuators[k];
    if (std::find(actions.actuators.begin(), actions.actuators.begin() + static_cast<long>(k), name) !=
        actions.actuators.begin() + static_cast<long>(k)) {
      throw std::logic_error(who + "actuator '" + name + "' is listed twice");
    }
  }
  const std::string dims = " (T=" + std::to_string(t) + ", U=" + std::to_string(u) + ")";
  CheckCount(who, "actions.controls", actions.controls.size(), t * u, "T*U", dims);
}

}  // namespace

// ---------------------------------------------------------------------------------------
// SensorRecord, RunRecord

void SensorRecord::CheckShapes(size_t t, const std::string& run_who) const {
  if (name.empty() || name == "." || name == ".." || name.find('/') != std::string::npos) {
    throw std::logic_error(run_who + "sensor name '" + name + "' cannot name a group (empty, '/', '.' or '..')");
  }
  const std::string who = run_who + "sensor '" + name + "': ";
  if (n_pins < 1) throw std::logic_error(who + "n_pins must be >= 1, got " + std::to_string(n_pins));
  if (attrs.count("n_pins") != 0) throw std::logic_error(who + "'n_pins' is not an attribute but the field");
  for (const auto& [key, value] : text_attrs) {
    if (attrs.count(key) != 0) throw std::logic_error(who + "attribute '" + key + "' is both numeric and text");
  }
  const size_t n = static_cast<size_t>(n_pins);
  const std::string dims = " (T=" + std::to_string(t) + ", N=" + std::to_string(n) + ")";
  // Each field against the product of its shape.
  CheckPinArrays(t, who);
  CheckCount(who, "gross_slip", gross_slip.size(), t, "T", dims);
  CheckCount(who, "normal_N", normal_N.size(), t * n, "T*N", dims);
  CheckCount(who, "tangential_N", tangential_N.size(), t * n * 2, "T*N*2", dims);
  CheckCount(who, "incipient", incipient.size(), t, "T", dims);
  if (!pin_first_slip_s.empty()) CheckCount(who, "pin_first_slip_s", pin_first_slip_s.size(), n, "N", dims);
  if (!images.empty() || !detected_px.empty() || !detected_valid.empty()) {
    // The image pipeline's arrays come together.
    CheckCount(who, "images", images.size(), t, "T", dims);
    CheckCount(who, "detected_px", detected_px.size(), t * n * 2, "T*N*2", dims);
    CheckCount(who, "detected_valid", detected_valid.size(), t * n, "T*N", dims);
    if (image_width < 1 || image_height < 1) {
      throw std::logic_error(who + "images of " + std::to_string(image_width) + " x " + std::to_string(image_height) +
                             " px (need >= 1 x 1)");
    }
  }
}

void SensorRecord::CheckPinArrays(size_t t, const std::string& who) const {
  const size_t n = static_cast<size_t>(std::max(n_pins, 0));
  const std::string dims = " (T=" + std::to_string(t) + ", N=" + std::to_string(n) + ")";
  CheckCount(who, "pos_px", pos_px.size(), t * n * 2, "T*N*2", dims);
  CheckCount(who, "valid", valid.size(), t * n, "T*N", dims);
  CheckCount(who, "pos_m", pos_m.size(), t * n * 3, "T*N*3", dims);
  CheckCount(who, "pin_slip", pin_slip.size(), t * n, "T*N", dims);
  CheckCount(who, "pin_contact", pin_contact.size(), t * n, "T*N", dims);
  if (!external_px.empty() || !external_m.empty()) {
    CheckCount(who, "external_px", external_px.size(), t * n * 2, "T*N*2", dims);
    CheckCount(who, "external_m", external_m.size(), t * n * 3, "T*N*3", dims);
  }
}

void RunRecord::CheckShapes() const {
  const std::string who = "RunRecord " + RunGroupName(index) + ": ";
  if (index < 0) throw std::logic_error("RunRecord: index must be >= 0, got " + std::to_string(index));
  if (time.empty()) throw std::logic_error(who + "time is empty (need T >= 1 frames)");
  if (sensors.empty()) throw std::logic_error(who + "has no sensor (need at least one)");
  const size_t t = time.size();
  for (size_t k = 0; k < sensors.size(); ++k) {
    sensors[k].CheckShapes(t, who);
    for (size_t j = 0; j < k; ++j) {
      if (sensors[j].name == sensors[k].name) {
        throw std::logic_error(who + "two sensors are named '" + sensors[k].name + "'");
      }
    }
  }
  CheckCount(who, "object_height_m", object_height_m.size(), t, "T", " (T=" + std::to_string(t) + ")");
  CheckActions(actions, t, who);
  for (const auto& [key, value] : text_attrs) {
    if (attrs.count(key) != 0) throw std::logic_error(who + "attribute '" + key + "' is both numeric and text");
  }
}

const SensorRecord* RunRecord::FindSensor(const std::string& name) const {
  for (const SensorRecord& s : sensors) {
    if (s.name == name) return &s;
  }
  return nullptr;
}

bool IsEventAttribute(const std::string& key) {
  static const char* const kEvents[] = {"gross_slip_onset_s", "incipient_onset_s", "incipient_lead_s",
                                        "object_fall_s",      "retract_start_s",   "predicted_onset_s",
                                        "coulomb_early_s",    "marker_onset_s"};
  return std::any_of(std::begin(kEvents), std::end(kEvents), [&](const char* e) { return key == e; });
}

bool IsSensorAttribute(const std::string& key) { return key == "skin_pattern"; }

std::string SensorNames(const RunRecord& run) {
  std::string out;
  for (const SensorRecord& s : run.sensors) out += (out.empty() ? "" : ", ") + s.name;
  return out;
}

std::string SensorPath(int layout_version, const std::string& name) {
  return layout_version >= 2 ? "sensors/" + name + "/" : std::string();
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
}  // namespace tactip
