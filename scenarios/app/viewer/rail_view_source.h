#pragma once
// The rail scene for the viewer: its initial state, stepped with zero controls (a stand-in
// until the steppable rail run drives the viewer).

#include <vector>

#include "scenarios/rail/rail_scenario.h"
#include "sim/view_source.h"

namespace tactip {

/// The rail scene of one config with its visual parts (rail beam, sensor housing), its pins
/// coloured as not in contact, seen from the side with the sensor and the object in view.
class RailViewSource : public ViewSource {
 public:
  /// Builds and compiles the scene (throws InputError/ModelError) and computes its initial
  /// state (contacts included).
  explicit RailViewSource(const RailScenarioConfig& cfg);

  /// One physics step with zero controls; throws SimulationError.
  bool Step() override;
  const Simulation& sim() const override { return sim_; }
  /// Every pin's contact geom grey (no contact).
  std::vector<GeomColour> Colours() const override;
  double time() const override { return sim_.time(); }
  /// Looks at the middle of the sensor and the object, from the side.
  CameraView Camera() const override;
  double force_scale_m_N() const override { return kForceScaleM_N; }

  /// Steps until the simulated time reaches `time_s`.
  void AdvanceTo(double time_s);
  /// The compiled scene shown.
  const CompiledModel& model() const { return scenario_.model(); }
  /// The object's geom, and the contact geom of every pin that has one.
  int object_geom() const { return object_geom_; }
  const std::vector<int>& pin_geoms() const { return pin_geoms_; }

  /// Contact force arrows: 20 mm for 1 N (pins carry tenths of a newton).
  static constexpr double kForceScaleM_N = 0.02;
  /// Camera distance from the look-at point (m).
  static constexpr double kCameraDistanceM = 0.12;

 private:
  RailScenario scenario_;
  Simulation sim_;
  std::vector<int> pin_geoms_;
  int object_geom_ = -1, sensor_body_ = -1, slider_body_ = -1;
};

}  // namespace tactip
