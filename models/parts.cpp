#include "models/parts.h"

#include <utility>

namespace tactip {

namespace {
std::vector<double> V(const std::array<double, 3>& a) { return {a[0], a[1], a[2]}; }
}  // namespace

ScenePart SliderPart(const SliderSpec& spec, std::vector<ScenePart> carried) {
  // The body on its joint, its own inertia, then what it carries.
  ScenePart part;
  part.bodies.emplace_back("body");
  mjcf::Element& body = part.bodies.back();
  body.Set("name", spec.body);
  if (spec.pos != std::array<double, 3>{}) body.Set("pos", V(spec.pos));
  body.Add("joint").Set("name", spec.joint).Set("type", "slide").Set("axis", V(spec.axis)).Set("damping", spec.damping_Ns_m);
  const double I = spec.inertia_kg_m2;
  body.Add("inertial").Set("pos", std::vector<double>{0, 0, 0}).Set("mass", spec.mass_kg)
      .Set("diaginertia", std::vector<double>{I, I, I});
  part.actuators.emplace_back("position");
  part.actuators.back().Set("name", spec.servo).Set("joint", spec.joint).Set("kp", spec.kp_N_m);
  for (ScenePart& c : carried) {
    for (mjcf::Element& b : c.bodies) body.Append(std::move(b));
    for (mjcf::Element& t : c.tendons) part.tendons.push_back(std::move(t));
    for (mjcf::Element& a : c.actuators) part.actuators.push_back(std::move(a));
    for (ObjectPartNames& o : c.objects) part.objects.push_back(std::move(o));
    for (SensorPartNames& s : c.sensors) part.sensors.push_back(std::move(s));
    part.n_collidable += c.n_collidable;
  }
  return part;
}

ScenePart BoxObjectPart(const BoxObjectSpec& spec) {
  ScenePart part;
  part.bodies.emplace_back("body");
  mjcf::Element& body = part.bodies.back();
  body.Set("name", spec.name).Set("pos", V(spec.pos));
  // Its joint: along z between its end stops, or free.
  mjcf::Element& joint = body.Add("joint");
  joint.Set("name", spec.name + "_joint");
  if (spec.free_joint) {
    joint.Set("type", "free");
  } else {
    joint.Set("type", "slide")
        .Set("axis", std::vector<double>{0, 0, 1})
        .Set("limited", "true")
        .Set("range", std::vector<double>{spec.range_m[0], spec.range_m[1]})
        .Set("frictionloss", spec.support_friction_N);
  }
  // Its mass, and its surface as the pins' contact partner.
  const double I = spec.mass_kg * (spec.half_size[0] * spec.half_size[0] + spec.half_size[1] * spec.half_size[1]) / 3.0;
  body.Add("inertial").Set("pos", std::vector<double>{0, 0, 0}).Set("mass", spec.mass_kg)
      .Set("diaginertia", std::vector<double>{I, I, I});
  body.Add("geom")
      .Set("name", spec.name + "_geom")
      .Set("type", "box")
      .Set("size", V(spec.half_size))
      .SetInt("contype", 2)
      .SetInt("conaffinity", 0)
      .SetInt("condim", 3)
      .Set("friction", std::vector<double>{spec.contact.friction, 0.005, 0.0001})
      .Set("solref", std::vector<double>{spec.contact.timeconst_s, 1.0})
      .Set("solimp", spec.contact.Solimp());
  part.objects.push_back({spec.name, spec.name, spec.name + "_joint", spec.free_joint, spec.name + "_geom", spec.mass_kg,
                          spec.free_joint ? 0.0 : spec.support_friction_N, spec.pos[2]});
  return part;
}

ScenePart SensorMountPart(const SensorMountSpec& spec, SkinPart skin, const std::vector<bool>& outer_sites) {
  // The mount (the sensor frame), its housing's inertia and look, its skin.
  ScenePart part;
  part.bodies.emplace_back("body");
  mjcf::Element& mount = part.bodies.back();
  mount.Set("name", spec.name + "/mount");
  if (spec.pos != std::array<double, 3>{}) mount.Set("pos", V(spec.pos));
  mount.Add("inertial").Set("pos", std::vector<double>{-0.02, 0, 0}).Set("mass", spec.mass_kg)
      .Set("diaginertia", std::vector<double>{1e-4, 1e-4, 1e-4});
  if (spec.housing) {
    mount.Add("geom")
        .Set("name", spec.name + "/housing")
        .Set("type", "cylinder")
        .Set("pos", std::vector<double>{-0.03, 0, 0})
        .Set("zaxis", std::vector<double>{1, 0, 0})
        .Set("size", std::vector<double>{spec.housing_radius_m, 0.028})
        .SetInt("contype", 0)
        .SetInt("conaffinity", 0)
        .Set("rgba", std::vector<double>{0.15, 0.15, 0.15, 1});
  }
  const int n_pins = static_cast<int>(skin.collidable.size());
  mount.Append(std::move(skin.body));
  part.tendons = std::move(skin.tendons);
  part.n_collidable = skin.n_collidable;
  part.sensors.push_back(
      {spec.name, spec.name + "/", spec.name + "/mount", n_pins, outer_sites, spec.carrier_joint, spec.press_servo});
  return part;
}

}  // namespace tactip
