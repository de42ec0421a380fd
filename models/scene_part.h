#pragma once
// A scene's MJCF assembled from named parts. Each part brings bodies for the world (a rig,
// an object, an arm carrying sensors), tendons and actuators, and names what the run must
// find of it: the actuators a controller commands, the object whose slip it follows, the
// tactile sensors. A scene writes the parts in the order they were added.

#include <string>
#include <vector>

#include "models/mjcf.h"
#include "models/skin.h"
#include "sim/sim_config.h"

namespace tactip {

/// The object a scene's sensors hold or press, by the names of its elements.
struct ObjectPartNames {
  std::string name;        ///< the object's name in events and summaries ("slider")
  std::string body;        ///< its body
  std::string joint;       ///< its joint: a slide joint along the vertical, or a free joint
  bool free_joint = false; ///< `joint` is a free joint (its vertical DOF is the third)
  std::string geom;        ///< the geom the sensors touch
  double mass_kg = 0.0;             ///< its mass
  double support_friction_N = 0.0;  ///< dry friction of what guides it besides the sensors (a rail's)
  double rest_height_m = 0.0;       ///< its body's height at rest (world z)
};

/// A tactile sensor of a scene, by the names of its elements.
struct SensorPartNames {
  std::string name;           ///< the sensor's name (its dataset group)
  std::string prefix;         ///< the prefix of its skin's elements ("NAME/")
  std::string mount_body;     ///< the body whose frame is the sensor frame
  int n_pins = 0;             ///< pins of its skin
  std::vector<bool> outer_sites;  ///< per pin: it carries an outer contact-point site
  std::string carrier_joint;  ///< the slide joint that carries it along the vertical, or "" (fixed)
  std::string press_actuator; ///< the actuator that moves it along its pressing axis, or ""
};

/// MuJoCo's contact budget of a scene with `n_collidable` pin contacts: one contact per pin
/// plus spare, and constraint rows for them (3 per contact with elliptic cones, 4 pyramidal)
/// plus joint limits and dry friction.
struct ContactBudget {
  int nconmax = 0;
  int njmax = 0;
};
ContactBudget SceneContactBudget(const SimConfig& sim, int n_collidable);

/// A scene root: model name, compiler settings, solver options from `sim`, and the contact
/// budget SceneContactBudget.
mjcf::Element SceneRoot(const std::string& model_name, const SimConfig& sim, const ContactConfig& contact,
                        double gravity_z, int n_collidable);

/// One part of a scene.
struct ScenePart {
  std::vector<mjcf::Element> bodies;     ///< children of the worldbody (bodies, geoms, lights)
  std::vector<mjcf::Element> tendons;    ///< children of <tendon>
  std::vector<mjcf::Element> actuators;  ///< children of <actuator>, each with a name
  std::vector<ObjectPartNames> objects;  ///< the object it is, if any
  std::vector<SensorPartNames> sensors;  ///< the tactile sensors it carries
  int n_collidable = 0;                  ///< pins of its sensors with a contact geom
};

/// A built scene: the MJCF text and what the run must find in it.
struct BuiltScene {
  std::string xml;
  int n_pins = 0;        ///< pins of each sensor (the first sensor's)
  int n_collidable = 0;  ///< pins with a contact geom, of all sensors
  std::vector<std::string> actuators;   ///< actuator names, in MJCF order (the controls' order)
  std::vector<ObjectPartNames> objects;  ///< in part order
  std::vector<SensorPartNames> sensors;  ///< in part order
};

/// The scene of `root` (its compiler, option and size settings: SceneRoot) and `parts`, in
/// order: every part's bodies in one worldbody, then every tendon, then every actuator
/// (a section left out when no part has any).
BuiltScene AssembleScene(mjcf::Element root, std::vector<ScenePart> parts);

}  // namespace tactip
