#include "sensors/run_recorder.h"

#include <stdexcept>

namespace tactip {

namespace {

template <class T>
void AppendAll(std::vector<T>& to, const std::vector<T>& from) {
  to.insert(to.end(), from.begin(), from.end());
}

}  // namespace

RunRecorder::RunRecorder(RunRecord& rec, int index, const std::vector<SensorGroup>& sensors,
                         const std::vector<std::string>& actuators, size_t expected_frames)
    : rec_(rec) {
  rec_ = RunRecord{};
  rec_.index = index;
  rec_.time.reserve(expected_frames);
  for (const SensorGroup& g : sensors) {
    SensorRecord& s = rec_.sensors.emplace_back();
    s.name = g.name;
    s.n_pins = g.n_pins;
  }
  rec_.actions.actuators = actuators;
}

void RunRecorder::Frame(double time_s, const std::vector<const SensorReading*>& readings, std::uint8_t gross_slip,
                        double object_height_m, const std::vector<double>& controls) {
  if (readings.size() != rec_.sensors.size() || controls.size() != rec_.actions.actuators.size()) {
    throw std::logic_error("run " + std::to_string(rec_.index) + ": a frame of " + std::to_string(readings.size()) +
                           " sensor readings and " + std::to_string(controls.size()) + " controls for a record of " +
                           std::to_string(rec_.sensors.size()) + " sensors and " +
                           std::to_string(rec_.actions.actuators.size()) + " actuators");
  }
  for (size_t k = 0; k < readings.size(); ++k) {
    const size_t n = static_cast<size_t>(rec_.sensors[k].n_pins);
    if (readings[k]->valid.size() != n) {
      throw std::logic_error("sensor '" + rec_.sensors[k].name + "': a reading of " +
                             std::to_string(readings[k]->valid.size()) + " pins for a group of " + std::to_string(n));
    }
  }
  // Checked first: a frame that does not fit leaves the record as it was.
  rec_.time.push_back(time_s);
  for (size_t k = 0; k < readings.size(); ++k) Append(*readings[k], gross_slip, rec_.sensors[k]);
  rec_.object_height_m.push_back(object_height_m);
  AppendAll(rec_.actions.controls, controls);
}

void RunRecorder::LabelGrossFrom(size_t first_frame) {
  for (SensorRecord& s : rec_.sensors) {
    for (size_t f = first_frame; f < s.gross_slip.size(); ++f) s.gross_slip[f] = 1;
  }
}

void RunRecorder::Images(size_t sensor, const ImageReading& r, int width, int height) {
  if (sensor >= rec_.sensors.size()) {
    throw std::logic_error("run " + std::to_string(rec_.index) + ": images of sensor " + std::to_string(sensor) +
                           " of " + std::to_string(rec_.sensors.size()));
  }
  SensorRecord& s = rec_.sensors[sensor];
  const size_t n = static_cast<size_t>(s.n_pins);
  const bool size_changed = !s.images.empty() && (s.image_width != width || s.image_height != height);
  if (r.detected_valid.size() != n || r.detected_px.size() != 2 * n || size_changed) {
    throw std::logic_error("sensor '" + s.name + "': images of " + std::to_string(r.detected_valid.size()) +
                           " pins, " + std::to_string(width) + " x " + std::to_string(height) +
                           " px, for a group of " + std::to_string(n) + " pins");
  }
  // Checked first: a frame that does not fit leaves the record as it was.
  s.image_width = width;
  s.image_height = height;
  s.images.push_back(r.image);
  AppendAll(s.detected_px, r.detected_px);
  AppendAll(s.detected_valid, r.detected_valid);
}

void RunRecorder::FirstSlips(size_t sensor, const std::vector<double>& first_slip_s) {
  if (sensor >= rec_.sensors.size() || first_slip_s.size() != static_cast<size_t>(rec_.sensors[sensor].n_pins)) {
    throw std::logic_error("run " + std::to_string(rec_.index) + ": first slips of " +
                           std::to_string(first_slip_s.size()) + " pins for sensor " + std::to_string(sensor) + " of " +
                           std::to_string(rec_.sensors.size()));
  }
  rec_.sensors[sensor].pin_first_slip_s = first_slip_s;
}

void RunRecorder::Append(const SensorReading& r, std::uint8_t gross_slip, SensorRecord& s) {
  AppendAll(s.pos_m, r.pos_m);
  AppendAll(s.pos_px, r.pos_px);
  AppendAll(s.valid, r.valid);
  AppendAll(s.external_m, r.external_m);
  AppendAll(s.external_px, r.external_px);
  AppendAll(s.normal_N, r.normal_N);
  AppendAll(s.tangential_N, r.tangential_N);
  AppendAll(s.pin_contact, r.pin_contact);
  AppendAll(s.pin_slip, r.pin_slip);
  s.incipient.push_back(r.incipient);
  s.gross_slip.push_back(gross_slip);
}

}  // namespace tactip
