#include "scenarios/app/viewer/rail_view_source.h"

#include <fmt/format.h>

#include "scenarios/app/viewer/pin_label_colours.h"

namespace tactip {

namespace {

// The config, checked as a scenario checks it before building its scene.
RailScenarioConfig Validated(RailScenarioConfig cfg) {
  ValidateConfig(cfg);
  return cfg;
}

// The rail scene with the parts that are only there to be seen.
SceneOptions WithVisualParts() {
  SceneOptions options;
  options.visual_geoms = true;
  return options;
}

// The protocol's phase at time t.
const char* PhaseAt(const RailSchedule& s, double t) {
  if (t < s.press_start) return "settle";
  if (t < s.press_end) return "press";
  if (t < s.lift_start) return "settle";
  if (t < s.lift_end) return "lift";
  if (t < s.retract_start) return "hold";
  return "retract";
}

}  // namespace

RailViewSource::RailViewSource(const RailScenarioConfig& cfg, int index, std::uint64_t seed)
    : cfg_(Validated(cfg)), scene_(cfg_, WithVisualParts()), index_(index), seed_(seed), run_(cfg_, scene_, index, seed) {}

bool RailViewSource::Step() {
  if (finished_) return false;
  if (run_.Step(rec_)) return true;
  run_.Finish(rec_);
  finished_ = true;
  return false;
}

bool RailViewSource::AdvanceTo(double time_s) {
  while (time() < time_s) {
    if (!Step()) return false;
  }
  return true;
}

std::vector<GeomColour> RailViewSource::Colours() const {
  std::vector<GeomColour> colours;
  for (size_t k = 0; k < run_.sensor_count(); ++k) {
    const TactileSensor& s = run_.sensor(k);
    for (const GeomColour& c : PinLabelColours(s.ids().pin_geom, s.pin_contact().data(), s.pin_slip().data())) {
      colours.push_back(c);
    }
  }
  return colours;
}

std::vector<int> RailViewSource::pin_geoms() const {
  std::vector<int> geoms;
  for (const SceneSensor& sensor : scene_.scene.sensors) {
    for (int g : sensor.ids.pin_geom) {
      if (g >= 0) geoms.push_back(g);
    }
  }
  return geoms;
}

CameraView RailViewSource::Camera() const {
  CameraView view;
  for (const SceneSensor& sensor : scene_.scene.sensors) view.look_at_bodies.push_back(sensor.ids.body);
  view.look_at_bodies.push_back(scene_.scene.object.body);
  view.distance_m = kCameraDistanceM;
  view.azimuth_deg = 80.0;
  view.elevation_deg = -20.0;
  return view;
}

std::string RailViewSource::Status() const {
  return fmt::format("run {} (seed {}): {}", index_, seed_, finished_ ? "ended" : PhaseAt(run_.schedule(), time()));
}

}  // namespace tactip
