#pragma once
// Generic scene parts any scene can be built from: a body on one actuated slide joint (an
// arm stage, a slider), an object (a box on a slide or free joint) and a tactile sensor's
// mount carrying its skin. Each is named by the caller; a sensor's skin carries its prefix.

#include <array>
#include <string>
#include <vector>

#include "models/scene_part.h"
#include "models/skin.h"

namespace tactip {

/// A body on one slide joint under a position servo (the `joint`'s name + the servo's).
struct SliderSpec {
  std::string body;                 ///< the body's name
  std::string joint;                ///< its slide joint's name
  std::string servo;                ///< its position servo's name
  std::array<double, 3> pos{};      ///< the body's position in its parent (m)
  std::array<double, 3> axis{1, 0, 0};  ///< the joint's axis
  double mass_kg = 0.5;             ///< the stage's own mass
  double inertia_kg_m2 = 1e-3;      ///< its diagonal inertia
  double kp_N_m = 1e5;              ///< servo stiffness
  double damping_Ns_m = 0.0;        ///< joint damping (implicit)
};

/// The slider of `spec` carrying the parts `carried` (their bodies inside it); its servo
/// comes before theirs, and their tendons, objects and sensors join it.
ScenePart SliderPart(const SliderSpec& spec, std::vector<ScenePart> carried = {});

/// A box the sensors press or hold: the scene's object.
struct BoxObjectSpec {
  std::string name = "box";          ///< body name; its joint is NAME_joint, its geom NAME_geom
  std::array<double, 3> pos{};       ///< its position in the world (m)
  std::array<double, 3> half_size{0.01, 0.01, 0.01};  ///< half sizes (m)
  double mass_kg = 0.05;
  bool free_joint = false;           ///< a free joint, or a slide joint along z
  std::array<double, 2> range_m{-0.1, 0.1};  ///< the slide joint's range (its end stops)
  double support_friction_N = 0.0;   ///< the slide joint's dry friction
  ContactConfig contact;             ///< its surface against the pins
};

/// The box of `spec` (its face touched by pins with contype 2).
ScenePart BoxObjectPart(const BoxObjectSpec& spec);

/// A tactile sensor's mount: a body whose frame is the sensor frame, carrying its skin.
struct SensorMountSpec {
  std::string name;                   ///< the sensor's name; its mount is NAME/mount, its elements NAME/...
  std::array<double, 3> pos{};        ///< the mount's position in its carrier (m)
  double mass_kg = 0.15;              ///< housing, camera and gel reservoir
  bool housing = false;               ///< a visual housing around the dome
  double housing_radius_m = 0.023;    ///< its radius
  std::string carrier_joint;          ///< the slide joint carrying it along the vertical, or ""
  std::string press_servo;            ///< the servo that moves it along its pressing axis, or ""
};

/// The mount of `spec` carrying `skin` (built with SkinNames{NAME/}) whose outer sites are
/// `outer_sites`.
ScenePart SensorMountPart(const SensorMountSpec& spec, SkinPart skin, const std::vector<bool>& outer_sites);

}  // namespace tactip
