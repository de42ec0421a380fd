#include "models/rail_rig.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include <fmt/format.h>

namespace tactip {

namespace {
constexpr double kSensorMassKg = 0.15;  // sensor housing, camera and gel reservoir
constexpr double kCullMarginM = 1e-3;   // pins within this distance of the stimulus keep a contact geom

std::vector<double> V3(double x, double y, double z) { return {x, y, z}; }
}  // namespace

double RailConfig::StimulusRadiusM() const {
  if (stimulus == "curved80") return 0.080;
  if (stimulus == "curved40") return 0.040;
  if (stimulus == "curved20") return 0.020;
  return 0.0;
}

double ArmConfig::Omega(double moving_mass_kg) const { return std::sqrt(kp_N_m / moving_mass_kg); }

double SensorCentreX(const SkinConfig& skin, double gap_m) { return -skin.OuterRadiusMm() * 1e-3 - gap_m; }

void SensorMountConfig::ValidateRules(size_t index) const {
  const std::string key = fmt::format("sensors.{}.name", index);
  const bool starts = !name.empty() && std::isalpha(static_cast<unsigned char>(name[0]));
  const bool rest = std::all_of(name.begin(), name.end(), [](char ch) {
    return std::isalnum(static_cast<unsigned char>(ch)) || ch == '_' || ch == '-';
  });
  if (!starts || !rest || name.size() > kMaxNameLength) {
    FailRule(key, name, fmt::format("a sensor name is 1-{} letters, digits, '_' or '-', starting with a letter",
                                    kMaxNameLength));
  }
}

std::vector<bool> RailCollidablePins(const SkinConfig& skin, const PinLattice& lattice, const RailConfig& rail,
                                     double max_depth_m, double offset_y_m) {
  const double R = skin.OuterRadiusMm() * 1e-3;
  const double rc = skin.ContactRadiusMm() * 1e-3;
  const double Rc = rail.StimulusRadiusM();
  const double cx = -R + max_depth_m;  // dome centre at the deepest press
  std::vector<bool> out(lattice.size());
  for (const auto& p : lattice.pins) {
    // Centre of the pin's contact sphere at the deepest press, object aligned.
    const double px = cx + (R - rc) * p.normal[0];
    const double py = offset_y_m + (R - rc) * p.normal[1];
    const double pz = (R - rc) * p.normal[2];
    if (Rc == 0.0) {
      out[p.index] = px + rc > -kCullMarginM;
    } else {
      const double d = std::sqrt((px - Rc) * (px - Rc) + py * py + pz * pz);
      out[p.index] = d < Rc + rc + kCullMarginM;
    }
  }
  return out;
}

double SensorMassKg(const SkinMechanics& mech, size_t n_pins) {
  return kSensorMassKg + mech.shell_mass_kg + static_cast<double>(n_pins) * mech.pin_mass_kg;
}

ContactBudget SceneContactBudget(const SimConfig& sim, int n_collidable) {
  ContactBudget b;
  b.nconmax = n_collidable + 8;
  const int rows_per_contact = sim.cone == "pyramidal" ? 4 : 3;
  b.njmax = rows_per_contact * b.nconmax + 16;
  return b;
}

mjcf::Element SceneRoot(const std::string& model_name, const SimConfig& sim, const ContactConfig& contact,
                        double gravity_z, int n_collidable) {
  mjcf::Element root("mujoco");
  root.Set("model", model_name);
  const bool exact_noslip = sim.noslip == "exact" && sim.noslip_iterations > 0;
  root.Add("compiler").Set("angle", "radian").Set("inertiafromgeom", "false");
  root.Add("option")
      .Set("timestep", sim.timestep_s)
      .Set("integrator", "Euler")
      .Set("solver", "Newton")
      .Set("jacobian", "auto")
      .Set("cone", sim.cone)
      .Set("impratio", sim.impratio)
      .SetInt("iterations", sim.iterations)
      .Set("tolerance", sim.tolerance)
      .SetInt("noslip_iterations", exact_noslip ? 0 : sim.noslip_iterations)
      .Set("noslip_tolerance", sim.noslip_tolerance)
      .Set("gravity", V3(0, 0, gravity_z));
  const ContactBudget budget = SceneContactBudget(sim, n_collidable);
  root.Add("size").SetInt("nconmax", budget.nconmax).SetInt("njmax", budget.njmax).SetInt("nuser_jnt", 1);
  const bool post_pass = sim.noslip_iterations > 0;
  if (post_pass && sim.free_sliding_speed_mm_s > 0.0) {
    root.Add("custom")
        .Add("numeric")
        .Set("name", kFreeSlidingNumeric)
        .SetInt("size", 1)
        .Set("data", std::vector<double>{sim.free_sliding_speed_mm_s * 1e-3});
  }
  if (exact_noslip) {
    // tactip's friction pass runs outside MuJoCo (tactip's Simulation reads this numeric);
    // a plain MuJoCo program loading this file runs without it, so its contacts creep.
    root.Comment(fmt::format("sim.noslip = exact: tactip replaces MuJoCo's noslip pass by its friction pass ({} rounds, "
                             "pre-sliding {} mm); plain MuJoCo runs this model without it",
                             sim.noslip_iterations, contact.presliding_mm));
    root.Add("custom")
        .Add("numeric")
        .Set("name", kFrictionPassNumeric)
        .SetInt("size", 2)
        .Set("data", std::vector<double>{static_cast<double>(sim.noslip_iterations), contact.presliding_mm * 1e-3});
  }
  return root;
}

std::vector<bool> RailOuterSitePins(const RailSceneSpec& spec, size_t n_pins) {
  std::vector<bool> out(n_pins, spec.external_markers || spec.options.outer_sites);
  if (!out.empty()) out[0] = true;  // the centre pin's contact point: the creep measurement
  return out;
}

namespace {

// The object's joint: the rail's vertical slide joint, or (SceneOptions::object_free_joint)
// a free joint held in place by heavy damping.
void AddObjectJoint(mjcf::Element& slider, const RailSceneSpec& spec) {
  mjcf::Element& joint = slider.Add("joint");
  joint.Set("name", RailNames::kSlide);
  if (spec.options.object_free_joint) {
    joint.Set("type", "free").Set("damping", SceneOptions::kFreeObjectDampingNs_m);
    return;
  }
  joint.Set("type", "slide")
      .Set("axis", V3(0, 0, 1))
      .Set("limited", "true")
      .Set("range", std::vector<double>{0.0, RailLayout::kRailTravel})
      .Set("solreflimit", std::vector<double>{0.005, 1.0})
      .Set("frictionloss", spec.rail.friction_N)
      .Set("damping", spec.rail.damping_Ns_m);
}

// Rail: (a visual beam,) the slider on its joint, the stimulus on it.
void AddRailAndObject(mjcf::Element& world, const RailSceneSpec& spec) {
  const bool visual = spec.options.visual_geoms;
  const double travel = RailLayout::kRailTravel;
  if (visual) {
    world.Add("geom")
        .Set("name", "rail_beam")
        .Set("type", "box")
        .Set("pos", V3(0.045, 0, RailLayout::kAxisHeight + 0.5 * travel))
        .Set("size", V3(0.01, 0.01, 0.5 * travel + 0.05))
        .SetInt("contype", 0)
        .SetInt("conaffinity", 0)
        .Set("rgba", std::vector<double>{0.4, 0.4, 0.45, 1});
  }
  mjcf::Element& slider = world.Add("body");
  slider.Set("name", RailNames::kSlider).Set("pos", V3(0, 0, RailLayout::kAxisHeight));
  AddObjectJoint(slider, spec);
  slider.Add("inertial").Set("pos", V3(0.01, 0, 0)).Set("mass", spec.object.mass_kg)
      .Set("diaginertia", V3(1e-4, 1e-4, 1e-4));
  const std::vector<double> friction{spec.contact.friction, 0.005, 0.0001};
  mjcf::Element& stim = slider.Add("geom");
  stim.Set("name", RailNames::kStimulus)
      .SetInt("contype", 2)
      .SetInt("conaffinity", 0)
      .SetInt("condim", 3)
      .Set("friction", friction)
      .Set("solref", std::vector<double>{spec.contact.timeconst_s, 1.0})
      .Set("solimp", spec.contact.Solimp())
      .Set("rgba", std::vector<double>{0.85, 0.6, 0.2, 1});
  const double Rc = spec.rail.StimulusRadiusM();
  if (Rc == 0.0) {
    // Flat: a 50 x 50 x 10 mm plate whose face is the plane x = 0 (clear for acrylic),
    // widened to reach 25 mm beyond every sensor's axis.
    double half_width = 0.025;
    for (const SensorMountConfig& s : spec.sensors) half_width = std::max(half_width, std::abs(s.offset_y_mm) * 1e-3 + 0.025);
    stim.Set("type", "box").Set("pos", V3(0.005, 0, 0)).Set("size", V3(0.005, half_width, 0.025));
    if (spec.rail.stimulus == "acrylic") stim.Set("rgba", std::vector<double>{0.8, 0.9, 1.0, 0.3});
    return;
  }
  // Curved: a sphere cap of radius Rc, apex at x = 0 (on a visual base plate).
  stim.Set("type", "sphere").Set("pos", V3(Rc, 0, 0)).Set("size", std::vector<double>{Rc});
  if (!visual) return;
  slider.Add("geom")
      .Set("name", "stimulus_plate")
      .Set("type", "box")
      .Set("pos", V3(RailLayout::kApexHeight + 0.003, 0, 0))
      .Set("size", V3(0.003, 0.03, 0.03))
      .SetInt("contype", 0)
      .SetInt("conaffinity", 0);
}

// One sensor's mount on the z stage: its body (sensor frame), a visual housing, its skin.
void AddSensor(mjcf::Element& stage, const RailSceneSpec& spec, const SensorMountConfig& mount, mjcf::Element skin_body) {
  mjcf::Element& sensor = stage.Add("body");
  sensor.Set("name", RailNames::SensorMount(mount.name));
  if (mount.offset_y_mm != 0.0) sensor.Set("pos", V3(0, mount.offset_y_mm * 1e-3, 0));
  sensor.Add("inertial").Set("pos", V3(-0.02, 0, 0)).Set("mass", kSensorMassKg).Set("diaginertia", V3(1e-4, 1e-4, 1e-4));
  if (spec.options.visual_geoms) {
    sensor.Add("geom")
        .Set("name", mount.Prefix() + "housing")
        .Set("type", "cylinder")
        .Set("pos", V3(-0.03, 0, 0))
        .Set("zaxis", V3(1, 0, 0))
        .Set("size", std::vector<double>{spec.skin.OuterRadiusMm() * 1e-3 + 0.003, 0.028})
        .SetInt("contype", 0)
        .SetInt("conaffinity", 0)
        .Set("rgba", std::vector<double>{0.15, 0.15, 0.15, 1});
  }
  sensor.Append(std::move(skin_body));
}

// Arm: x stage (normal), z stage (vertical), a mount per sensor (with a visual housing) and
// its skin. `m_sensors` is the mass of all sensors.
void AddArmAndSensors(mjcf::Element& world, const RailSceneSpec& spec, double m_sensors,
                      std::vector<mjcf::Element> skin_bodies) {
  const double mx = 2.0 * spec.arm.stage_mass_kg + m_sensors;
  const double mz = spec.arm.stage_mass_kg + m_sensors;
  const double x0 = SensorCentreX(spec.skin, spec.rail.approach_gap_mm * 1e-3);
  mjcf::Element& ax = world.Add("body");
  ax.Set("name", "arm_x_stage").Set("pos", V3(x0, 0, RailLayout::kAxisHeight));
  ax.Add("joint").Set("name", RailNames::kArmX).Set("type", "slide").Set("axis", V3(1, 0, 0))
      .Set("damping", 2.0 * spec.arm.damping_ratio * std::sqrt(spec.arm.kp_N_m * mx));
  ax.Add("inertial").Set("pos", V3(0, 0, 0)).Set("mass", spec.arm.stage_mass_kg).Set("diaginertia", V3(1e-3, 1e-3, 1e-3));
  mjcf::Element& az = ax.Add("body");
  az.Set("name", "arm_z_stage");
  az.Add("joint").Set("name", RailNames::kArmZ).Set("type", "slide").Set("axis", V3(0, 0, 1))
      .Set("damping", 2.0 * spec.arm.damping_ratio * std::sqrt(spec.arm.kp_N_m * mz));
  az.Add("inertial").Set("pos", V3(0, 0, 0)).Set("mass", spec.arm.stage_mass_kg).Set("diaginertia", V3(1e-3, 1e-3, 1e-3));
  for (size_t k = 0; k < spec.sensors.size(); ++k) AddSensor(az, spec, spec.sensors[k], std::move(skin_bodies[k]));
}

}  // namespace

BuiltScene BuildRailScene(const RailSceneSpec& spec) {
  const PinLattice lattice = PinLattice::Build(spec.skin);
  const SkinMechanics mech = SkinMechanics::From(spec.skin, lattice.size());
  // A skin per sensor, its elements prefixed with the sensor's name.
  std::vector<mjcf::Element> skin_bodies, tendons;
  int n_collidable = 0;
  for (const SensorMountConfig& mount : spec.sensors) {
    std::vector<bool> collidable =
        RailCollidablePins(spec.skin, lattice, spec.rail, spec.max_depth_m, mount.offset_y_mm * 1e-3);
    if (spec.options.all_pins_collide) collidable.assign(lattice.size(), true);
    SkinPart skin = BuildSkin(spec.skin, spec.contact, lattice, collidable, spec.sim.timestep_s,
                              RailOuterSitePins(spec, lattice.size()), SkinNames{mount.Prefix()});
    n_collidable += skin.n_collidable;
    skin_bodies.push_back(std::move(skin.body));
    for (auto& t : skin.tendons) tendons.push_back(std::move(t));
  }

  mjcf::Element root = SceneRoot("tactip_rail", spec.sim, spec.contact, -9.81, n_collidable);
  if (spec.sim.SlidingTimestep() < spec.sim.timestep_s) {
    root.Comment(fmt::format("sim.sliding_timestep_s: tactip steps {:.6g} s from the gross-slip onset on; plain MuJoCo "
                             "runs this model at timestep {:.6g} s throughout",
                             spec.sim.SlidingTimestep(), spec.sim.timestep_s));
  }
  mjcf::Element& world = root.Add("worldbody");
  if (spec.options.visual_geoms) world.Add("light").Set("pos", V3(-0.2, -0.2, 0.4)).Set("dir", V3(1, 1, -1));
  AddRailAndObject(world, spec);
  const double m_sensors = static_cast<double>(spec.sensors.size()) * SensorMassKg(mech, lattice.size());
  AddArmAndSensors(world, spec, m_sensors, std::move(skin_bodies));

  // Passive skin coupling and the arm servos.
  if (!tendons.empty()) {
    mjcf::Element& tendon = root.Add("tendon");
    for (auto& t : tendons) tendon.Append(std::move(t));
  }
  mjcf::Element& act = root.Add("actuator");
  act.Add("position").Set("name", RailNames::kServoX).Set("joint", RailNames::kArmX).Set("kp", spec.arm.kp_N_m);
  act.Add("position").Set("name", RailNames::kServoZ).Set("joint", RailNames::kArmZ).Set("kp", spec.arm.kp_N_m);

  BuiltScene out;
  out.xml = root.ToXml();
  out.n_pins = static_cast<int>(lattice.size());
  out.n_collidable = n_collidable;
  return out;
}

}  // namespace tactip
