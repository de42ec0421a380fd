#include "models/contact_rig.h"

#include <cmath>

#include "models/rail_rig.h"

namespace tactip {

std::string BuildContactRig(const ContactRigSpec& spec) {
  const PinLattice lattice = PinLattice::Build(spec.skin);
  // Only pins that can reach the plate at the deepest press carry a contact geom.
  RailConfig flat;
  flat.stimulus = "flat";
  const auto collidable = RailCollidablePins(spec.skin, lattice, flat, spec.max_depth_m);
  SkinPart skin = BuildSkin(spec.skin, spec.contact, lattice, collidable, spec.sim.timestep_s);

  mjcf::Element root = SceneRoot("tactip_contact_rig", spec.sim, spec.contact, 0.0, skin.n_collidable);

  mjcf::Element& world = root.Add("worldbody");
  // Sensor fixed in the world, dome centre at x = -R so the apex is at x = 0.
  mjcf::Element& sensor = world.Add("body");
  sensor.Set("name", ContactRigNames::kSensor).Set("pos", std::vector<double>{-spec.skin.OuterRadiusMm() * 1e-3, 0, 0});
  sensor.Append(std::move(skin.body));

  // Plate carriage: normal and tangential slide joints under stiff, critically damped servos.
  const double c = 2.0 * std::sqrt(spec.servo_kp_N_m * spec.plate_mass_kg);
  mjcf::Element& plate = world.Add("body");
  plate.Set("name", ContactRigNames::kPlate).Set("pos", std::vector<double>{spec.gap_m, 0, 0});
  for (const char* j : {ContactRigNames::kNormal, ContactRigNames::kShear}) {
    const bool normal = std::string(j) == ContactRigNames::kNormal;
    plate.Add("joint")
        .Set("name", j)
        .Set("type", "slide")
        .Set("axis", normal ? std::vector<double>{1, 0, 0} : std::vector<double>{0, 1, 0})
        .Set("damping", c);
  }
  plate.Add("inertial").Set("pos", std::vector<double>{0.005, 0, 0}).Set("mass", spec.plate_mass_kg)
      .Set("diaginertia", std::vector<double>{1e-4, 1e-4, 1e-4});
  plate.Add("geom")
      .Set("name", ContactRigNames::kPlateGeom)
      .Set("type", "box")
      .Set("pos", std::vector<double>{0.005, 0, 0})
      .Set("size", std::vector<double>{0.005, spec.plate_half_length_m, 0.03})
      .SetInt("contype", 2)
      .SetInt("conaffinity", 0)
      .SetInt("condim", 3)
      .Set("friction", std::vector<double>{spec.contact.friction, 0.005, 0.0001})
      .Set("solref", std::vector<double>{spec.contact.timeconst_s, 1.0})
      .Set("solimp", spec.contact.Solimp());

  if (!skin.tendons.empty()) {
    mjcf::Element& tendon = root.Add("tendon");
    for (auto& t : skin.tendons) tendon.Append(std::move(t));
  }
  mjcf::Element& act = root.Add("actuator");
  act.Add("position").Set("name", ContactRigNames::kServoNormal).Set("joint", ContactRigNames::kNormal)
      .Set("kp", spec.servo_kp_N_m);
  act.Add("position").Set("name", ContactRigNames::kServoShear).Set("joint", ContactRigNames::kShear)
      .Set("kp", spec.servo_kp_N_m);
  return root.ToXml();
}

}  // namespace tactip
