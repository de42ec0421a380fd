#pragma once
// A compiled scene and what its parts tell the run: the actuators a controller commands, the
// object whose slip, loss and hold the run follows, and the tactile sensors that touch it.
// Built from the parts' MJCF (models/scene_part.h) by looking their named elements up.

#include <optional>
#include <string>
#include <vector>

#include "models/scene_part.h"
#include "models/skin.h"
#include "sensors/tactile_sensor.h"
#include "sim/simulation.h"

namespace tactip {

/// An actuator of the scene; a controller gives one control per actuator, in scene order.
struct SceneActuator {
  std::string name;
  int id = -1;  ///< MuJoCo actuator id
};

/// The body the sensors hold or press: the run follows its slip on each sensor, its loss
/// and whether it is held.
struct SceneObject {
  std::string name;                 ///< its name in events and summaries
  int body = -1;                    ///< its body
  int up_dof = -1;                  ///< the DOF of its motion along the vertical
  int contact_geom = -1;            ///< the geom the sensors touch (its friction is set per run)
  double mass_kg = 0.0;             ///< its mass
  double support_friction_N = 0.0;  ///< dry friction of what guides it besides the sensors
  double rest_height_m = 0.0;       ///< its body's height at rest; a record's object_height_m is relative to it
};

/// A tactile sensor of the scene: its elements, what its cameras see and how it is carried.
struct SceneSensor {
  TactileSensorIds ids;
  TactileSensorSpec spec;
  SkinConfig skin;           ///< its skin's design (the shell's gel damper follows it)
  std::string prefix;        ///< the prefix of its elements ("NAME/")
  int n_pins = 0;
  int carrier_up_dof = -1;   ///< the DOF carrying it along the vertical, or -1 (fixed in the world)
  int press_actuator = -1;   ///< index (in the scene's actuators) of what moves it along its pressing axis, or -1
};

/// A compiled scene, shared read-only by its runs (each copies the model).
struct Scene {
  BuiltScene built;               ///< the MJCF text and the parts' names
  std::optional<CompiledModel> model;
  std::vector<SceneActuator> actuators;
  SceneObject object;
  std::vector<SceneSensor> sensors;

  /// Compiles `built` and looks up its parts' elements: its one object and every sensor,
  /// whose specs and skins `specs` and `skins` give in the same order. Throws ModelError
  /// naming a missing element or a scene without one object or with a sensor unaccounted for.
  static Scene Compile(BuiltScene built, std::vector<TactileSensorSpec> specs, const std::vector<SkinConfig>& skins);

  /// The sensors' camera frame rate (Hz): every sensor of a scene films at the same rate.
  double frame_rate_hz() const { return sensors.front().spec.camera.frame_rate_hz; }
  /// Pins of all sensors.
  int total_pins() const;
};

}  // namespace tactip
