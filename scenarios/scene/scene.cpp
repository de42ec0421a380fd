#include "scenarios/scene/scene.h"

#include <fmt/format.h>

#include "sim/base/errors.h"

namespace tactip {

namespace {

// The object's elements; its vertical DOF is its slide joint's, or a free joint's third.
SceneObject BindObject(const CompiledModel& m, const ObjectPartNames& names) {
  SceneObject o;
  o.name = names.name;
  o.body = m.BodyId(names.body);
  o.up_dof = m.JointDofAdr(m.JointId(names.joint)) + (names.free_joint ? 2 : 0);
  o.contact_geom = m.GeomId(names.geom);
  o.mass_kg = names.mass_kg;
  o.support_friction_N = names.support_friction_N;
  o.rest_height_m = names.rest_height_m;
  return o;
}

// A sensor's elements, and the actuator that presses it (by its index among the scene's).
SceneSensor BindSensor(const CompiledModel& m, const BuiltScene& built, const SensorPartNames& names,
                       TactileSensorSpec spec, const SkinConfig& skin) {
  SceneSensor s;
  s.ids = TactileSensorIds::Find(m, names.mount_body, names.n_pins, names.outer_sites, SkinNames{names.prefix});
  s.spec = std::move(spec);
  s.skin = skin;
  s.prefix = names.prefix;
  s.n_pins = names.n_pins;
  if (!names.carrier_joint.empty()) s.carrier_up_dof = m.JointDofAdr(m.JointId(names.carrier_joint));
  for (size_t k = 0; k < built.actuators.size(); ++k) {
    if (built.actuators[k] == names.press_actuator) s.press_actuator = static_cast<int>(k);
  }
  if (!names.press_actuator.empty() && s.press_actuator < 0) {
    throw ModelError(fmt::format("sensor '{}': no actuator '{}' presses it", names.name, names.press_actuator));
  }
  return s;
}

}  // namespace

Scene Scene::Compile(BuiltScene built, std::vector<TactileSensorSpec> specs, const std::vector<SkinConfig>& skins) {
  if (built.objects.size() != 1) {
    throw ModelError(fmt::format("a scene holds one object; this one has {}", built.objects.size()));
  }
  if (built.sensors.empty() || specs.size() != built.sensors.size() || skins.size() != built.sensors.size()) {
    throw ModelError(fmt::format("the scene has {} tactile sensors, {} specs and {} skins", built.sensors.size(),
                                 specs.size(), skins.size()));
  }
  Scene scene;
  scene.model.emplace(CompiledModel::FromXml(built.xml));
  const CompiledModel& m = *scene.model;
  for (const std::string& name : built.actuators) scene.actuators.push_back({name, m.ActuatorId(name)});
  scene.object = BindObject(m, built.objects.front());
  for (size_t k = 0; k < built.sensors.size(); ++k) {
    scene.sensors.push_back(BindSensor(m, built, built.sensors[k], std::move(specs[k]), skins[k]));
    if (scene.sensors.back().spec.camera.frame_rate_hz != scene.sensors.front().spec.camera.frame_rate_hz) {
      throw ModelError(fmt::format("sensor '{}' films at {} Hz, sensor '{}' at {} Hz: the sensors of a scene share "
                                   "one frame rate",
                                   built.sensors[k].name, scene.sensors.back().spec.camera.frame_rate_hz,
                                   built.sensors.front().name, scene.sensors.front().spec.camera.frame_rate_hz));
    }
  }
  scene.built = std::move(built);
  return scene;
}

int Scene::total_pins() const {
  int n = 0;
  for (const SceneSensor& s : sensors) n += s.n_pins;
  return n;
}

}  // namespace tactip
