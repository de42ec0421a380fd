#include "scenarios/app/viewer/rail_view_source.h"

#include "models/rail_rig.h"
#include "models/skin.h"

namespace tactip {

namespace {

// The rail scene with the parts that are only there to be seen.
SceneOptions WithVisualParts() {
  SceneOptions options;
  options.visual_geoms = true;
  return options;
}

}  // namespace

RailViewSource::RailViewSource(const RailScenarioConfig& cfg)
    : scenario_(cfg, WithVisualParts()), sim_(scenario_.model()) {
  const CompiledModel& m = scenario_.model();
  object_geom_ = m.GeomId(RailNames::kStimulus);
  sensor_body_ = m.BodyId(RailNames::kSensor);
  slider_body_ = m.BodyId(RailNames::kSlider);
  // Pins that cannot reach the object have no contact geom.
  for (int i = 0; i < scenario_.n_pins(); ++i) {
    try {
      pin_geoms_.push_back(m.GeomId(SkinNames::PinGeom(i)));
    } catch (const ModelError&) {
      // culled: this pin has no contact geom
    }
  }
  sim_.Forward();
}

bool RailViewSource::Step() {
  sim_.Step();
  return true;
}

void RailViewSource::AdvanceTo(double time_s) {
  while (sim_.time() < time_s) Step();
}

std::vector<GeomColour> RailViewSource::Colours() const {
  std::vector<GeomColour> colours;
  colours.reserve(pin_geoms_.size());
  for (int g : pin_geoms_) colours.push_back({g, PinColours::kNoContact});
  return colours;
}

CameraView RailViewSource::Camera() const {
  CameraView view;
  view.look_at_bodies = {sensor_body_, slider_body_};
  view.distance_m = kCameraDistanceM;
  view.azimuth_deg = 80.0;
  view.elevation_deg = -20.0;
  return view;
}

}  // namespace tactip
