#pragma once
// One tactile sensor of a scene run: what it sees, its pins' friction, its rendered frames,
// and the history of its pins from the release to the gross-slip onset.

#include <cstdint>
#include <optional>
#include <vector>

#include "scenarios/scene/scene.h"
#include "sensors/friction_law.h"
#include "sensors/image_pipeline.h"
#include "sensors/tactile_sensor.h"

namespace tactip {

/// A sensor of the run and its per-pin history. One per sensor per run.
struct SensorChannel {
  TactileSensor sensor;
  FrictionLaw friction;
  /// Per pin in contact at the release: its first frame labelled slipping, from the release
  /// to the onset's confirmation (NaN: none).
  std::vector<double> first_slip_frame_s;
  std::vector<std::uint8_t> contact_at_release;  ///< per pin: in contact when the release started
  std::vector<double> first_slip_s;              ///< per pin: first step labelled slipping, release to onset
  std::optional<SensorImagePipeline> imaging;    ///< rendered frames and blob tracking (images.enabled)

  /// Sensor `k` of a run with seed `run_seed` and friction `mu`: its noise streams and pin
  /// friction spread are the run's streams 1-3 for the first sensor and streams of its own
  /// (below stream 100 + k) for the others; its rendered frames' pixel noise is stream 4.
  /// Sets its pins' friction in `model`.
  static SensorChannel Make(const SceneSensor& s, size_t k, std::uint64_t run_seed, double mu, int object_geom,
                            const ContactConfig& contact, const LabelConfig& labels, const TactileImageConfig& images,
                            CompiledModel& model);
};

}  // namespace tactip
