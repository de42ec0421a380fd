#pragma once
// The rail scene for the viewer: one run of the rail protocol (press, lift, hold, retract
// until the object falls), stepped as the viewer asks, with its pins coloured by the run's
// contact labels.

#include <cstdint>
#include <string>
#include <vector>

#include "scenarios/rail/rail_run.h"
#include "sim/view_source.h"

namespace tactip {

/// Run `index` of a rail config with master seed `seed`, on the scene with its visual parts
/// (rail beam, sensor housing, light), seen from the side with the sensor and the object in
/// view. It simulates and records exactly what `generate` does for that run: the visual
/// parts do not collide and carry no mass, so they change no physics.
class RailViewSource : public ViewSource {
 public:
  /// Validates `cfg`, builds and compiles the scene (throws InputError/ModelError) and sets
  /// the run up at its initial state.
  RailViewSource(const RailScenarioConfig& cfg, int index, std::uint64_t seed);
  RailViewSource(const RailViewSource&) = delete;
  RailViewSource& operator=(const RailViewSource&) = delete;

  /// One step of the run; false once the protocol has ended (the record is then complete).
  /// Throws SimulationError.
  bool Step() override;
  const Simulation& sim() const override { return run_.simulation(); }
  /// The pins by the labels of the sensors' last contact read-out: stick green, slip red,
  /// no contact grey. The run reads the contacts at every camera frame, and at every step
  /// from the lift on until the gross-slip onset is found.
  std::vector<GeomColour> Colours() const override;
  double time() const override { return run_.time(); }
  /// Looks at the middle of the sensors and the object, from the side.
  CameraView Camera() const override;
  double force_scale_m_N() const override { return kForceScaleM_N; }
  /// "run K (seed S): PHASE", the protocol's phase now (press, lift, hold, retract...).
  std::string Status() const override;

  /// Steps until the simulated time reaches `time_s`; false if the run ended before.
  bool AdvanceTo(double time_s);
  /// True once the run has ended.
  bool finished() const { return finished_; }
  /// The latest time the run can last (s): the protocol gives up then if the object has
  /// not fallen.
  double give_up_s() const { return run_.schedule().give_up; }

  /// The compiled scene shown.
  const CompiledModel& model() const { return *scene_.scene.model; }
  /// What the run has recorded so far (every camera frame up to now), as `generate` does.
  const RunRecord& record() const { return rec_; }
  /// The sensor (its pins' labels and geoms).
  const TactileSensor& sensor() const { return run_.sensor(); }
  /// The object's geom, and the contact geom of every pin that has one.
  int object_geom() const { return scene_.scene.object.contact_geom; }
  std::vector<int> pin_geoms() const;
  int index() const { return index_; }
  std::uint64_t seed() const { return seed_; }

  /// Contact force arrows: 20 mm for 1 N (pins carry tenths of a newton).
  static constexpr double kForceScaleM_N = 0.02;
  /// Camera distance from the look-at point (m).
  static constexpr double kCameraDistanceM = 0.12;

 private:
  const RailScenarioConfig cfg_;  // the run and the scene refer to these two
  const RailScene scene_;
  const int index_;
  const std::uint64_t seed_;
  RailRun run_;
  RunRecord rec_;
  bool finished_ = false;
};

}  // namespace tactip
