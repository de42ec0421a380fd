#pragma once
// Configuration of the rail protocol (the `rail` and `incipient` scenarios): every
// section, the cross-field rules and the scene it describes.

#include "models/rail_rig.h"
#include "scenarios/rail/run_health.h"
#include "sensors/camera.h"
#include "sensors/labels.h"
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
  HealthConfig health;

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
    v.Section("health", health);
  }
  /// Cross-field rules, including the timestep stability limit of the built model.
  void ValidateRules() const;
  /// The scene spec for this config (deepest press includes the depth jitter).
  RailSceneSpec SceneSpec() const;
};

}  // namespace tactip
