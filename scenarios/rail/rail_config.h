#pragma once
// Configuration of the rail protocol (the `rail` and `incipient` scenarios): every
// section, the cross-field rules and the scene it describes.

#include <string>
#include <vector>

#include "models/rail_rig.h"
#include "scenarios/scene/run_health.h"
#include "sensors/camera.h"
#include "sensors/labels.h"
#include "sensors/marker_labels.h"
#include "sensors/tactile_image.h"
#include "sim/sim_config.h"

namespace tactip {

/// Full configuration of the rail scenario; every field is documented in its section.
struct RailScenarioConfig {
  SimConfig sim;
  ObjectConfig object;
  ContactConfig contact;
  RailConfig rail;
  SkinConfig skin;
  ArmConfig arm;
  CameraConfig sensor;
  ExternalCameraConfig external;
  LabelConfig labels;
  MarkerCameraConfig marker_camera;
  HealthConfig health;
  TactileImageConfig images;
  std::vector<SensorMountConfig> sensors{SensorMountConfig{}};  ///< the TacTips on the arm (one by default)

  template <class V>
  void Visit(V& v) {
    v.Section("sim", sim);
    v.Section("object", object);
    v.Section("contact", contact);
    v.Section("rail", rail);
    v.Section("skin", skin);
    v.Section("arm", arm);
    v.Section("sensor", sensor);
    v.Section("external", external);
    v.Section("labels", labels);
    v.Section("marker_camera", marker_camera);
    v.Section("health", health);
    v.Section("images", images);
    v.List("sensors", sensors);
  }
  /// Cross-field rules, including the timestep stability limit of the built model.
  void ValidateRules() const;
  /// The scene spec for this config (deepest press includes the depth jitter): the lean
  /// scene, with every pin's outer contact point only for the external camera.
  RailSceneSpec SceneSpec() const;
};

/// The step `--auto-timestep` picks for a config and what binds it.
struct TimestepChoice {
  double timestep_s = 0.0;  ///< the chosen step: the camera frame period divided by a whole number
  double bound_s = 0.0;     ///< the smallest of the bounds, before rounding down to the frame period
  std::string binding;      ///< which bound that is: stability, accuracy, the contact or one camera frame
  double stable_s = 0.0;    ///< the largest stable step (LargestStableTimestep)
  std::string stable_mode;  ///< the mode that sets it
};

/// The largest step for `cfg` that is stable (every timestep-limiting mode, damping as
/// configured), no larger than the configured sim.timestep_s (the accuracy cap: 2 ms by
/// default), no larger than contact.timeconst_s / 2 (the contact is kept as configured)
/// and no longer than one camera frame, rounded down so that a frame is a whole number of
/// steps. Only `cfg`'s bounds need to hold; its cross-field rules are not checked.
TimestepChoice ChooseTimestep(const RailScenarioConfig& cfg);

}  // namespace tactip
