#include "models/rail_rig.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include <fmt/format.h>

#include "models/parts.h"

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

void RailConfig::ValidateRules() const {
  if (retract_speed_max_mm_s != 0.0 && retract_speed_max_mm_s < retract_speed_mm_s) {
    FailRule("rail.retract_speed_max_mm_s", retract_speed_max_mm_s,
             fmt::format("must be 0 (one speed) or at least rail.retract_speed_mm_s = {} mm/s",
                         config_detail::FormatReal(retract_speed_mm_s)));
  }
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

// The stimulus on the slider: a flat plate (clear for acrylic) or a sphere cap (on a
// visual base plate).
void AddStimulus(mjcf::Element& slider, const RailSceneSpec& spec) {
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
  if (!spec.options.visual_geoms) return;
  slider.Add("geom")
      .Set("name", "stimulus_plate")
      .Set("type", "box")
      .Set("pos", V3(RailLayout::kApexHeight + 0.003, 0, 0))
      .Set("size", V3(0.003, 0.03, 0.03))
      .SetInt("contype", 0)
      .SetInt("conaffinity", 0);
}

// Rail: (a light and a visual beam,) the slider on its joint, the stimulus on it: the
// scene's object.
ScenePart RailPart(const RailSceneSpec& spec) {
  ScenePart part;
  const double travel = RailLayout::kRailTravel;
  if (spec.options.visual_geoms) {
    part.bodies.emplace_back("light");
    part.bodies.back().Set("pos", V3(-0.2, -0.2, 0.4)).Set("dir", V3(1, 1, -1));
    part.bodies.emplace_back("geom");
    part.bodies.back()
        .Set("name", "rail_beam")
        .Set("type", "box")
        .Set("pos", V3(0.045, 0, RailLayout::kAxisHeight + 0.5 * travel))
        .Set("size", V3(0.01, 0.01, 0.5 * travel + 0.05))
        .SetInt("contype", 0)
        .SetInt("conaffinity", 0)
        .Set("rgba", std::vector<double>{0.4, 0.4, 0.45, 1});
  }
  part.bodies.emplace_back("body");
  mjcf::Element& slider = part.bodies.back();
  slider.Set("name", RailNames::kSlider).Set("pos", V3(0, 0, RailLayout::kAxisHeight));
  AddObjectJoint(slider, spec);
  slider.Add("inertial").Set("pos", V3(0.01, 0, 0)).Set("mass", spec.object.mass_kg)
      .Set("diaginertia", V3(1e-4, 1e-4, 1e-4));
  AddStimulus(slider, spec);
  part.objects.push_back({RailNames::kSlider, RailNames::kSlider, RailNames::kSlide, spec.options.object_free_joint,
                          RailNames::kStimulus, spec.object.mass_kg, spec.rail.friction_N, RailLayout::kAxisHeight});
  return part;
}

// One sensor's mount on the arm's z stage, with its skin: a contact geom on the pins that
// can reach the stimulus.
ScenePart RailSensorPart(const RailSceneSpec& spec, const PinLattice& lattice, const SensorMountConfig& mount) {
  std::vector<bool> collidable =
      RailCollidablePins(spec.skin, lattice, spec.rail, spec.max_depth_m, mount.offset_y_mm * 1e-3);
  if (spec.options.all_pins_collide) collidable.assign(lattice.size(), true);
  const std::vector<bool> outer = RailOuterSitePins(spec, lattice.size());
  SensorMountSpec m;
  m.name = mount.name;
  m.pos = {0, mount.offset_y_mm * 1e-3, 0};
  m.mass_kg = kSensorMassKg;
  m.housing = spec.options.visual_geoms;
  m.housing_radius_m = spec.skin.OuterRadiusMm() * 1e-3 + 0.003;
  m.carrier_joint = RailNames::kArmZ;
  m.press_servo = RailNames::kServoX;
  return SensorMountPart(
      m, BuildSkin(spec.skin, spec.contact, lattice, collidable, spec.sim.timestep_s, outer, SkinNames{mount.Prefix()}),
      outer);
}

// Arm: an x stage (normal) carrying a z stage (vertical) carrying the sensor parts `sensors`
// (of total mass `m_sensors`); each stage under its position servo.
ScenePart ArmPart(const RailSceneSpec& spec, double m_sensors, std::vector<ScenePart> sensors) {
  const double mx = 2.0 * spec.arm.stage_mass_kg + m_sensors;
  const double mz = spec.arm.stage_mass_kg + m_sensors;
  SliderSpec x{"arm_x_stage", RailNames::kArmX, RailNames::kServoX, {}, {1, 0, 0}, spec.arm.stage_mass_kg, 1e-3,
               spec.arm.kp_N_m, 2.0 * spec.arm.damping_ratio * std::sqrt(spec.arm.kp_N_m * mx)};
  x.pos = {SensorCentreX(spec.skin, spec.rail.approach_gap_mm * 1e-3), 0, RailLayout::kAxisHeight};
  const SliderSpec z{"arm_z_stage", RailNames::kArmZ, RailNames::kServoZ, {}, {0, 0, 1}, spec.arm.stage_mass_kg, 1e-3,
                     spec.arm.kp_N_m, 2.0 * spec.arm.damping_ratio * std::sqrt(spec.arm.kp_N_m * mz)};
  std::vector<ScenePart> stage;
  stage.push_back(SliderPart(z, std::move(sensors)));
  return SliderPart(x, std::move(stage));
}

}  // namespace

BuiltScene BuildRailScene(const RailSceneSpec& spec) {
  const PinLattice lattice = PinLattice::Build(spec.skin);
  const SkinMechanics mech = SkinMechanics::From(spec.skin, lattice.size());
  // A sensor part per mount, its elements prefixed with the sensor's name.
  std::vector<ScenePart> sensors;
  int n_collidable = 0;
  for (const SensorMountConfig& mount : spec.sensors) {
    sensors.push_back(RailSensorPart(spec, lattice, mount));
    n_collidable += sensors.back().n_collidable;
  }
  mjcf::Element root = SceneRoot("tactip_rail", spec.sim, spec.contact, -9.81, n_collidable);
  if (spec.sim.SlidingTimestep() < spec.sim.timestep_s) {
    root.Comment(fmt::format("sim.sliding_timestep_s: tactip steps {:.6g} s from the gross-slip onset on; plain MuJoCo "
                             "runs this model at timestep {:.6g} s throughout",
                             spec.sim.SlidingTimestep(), spec.sim.timestep_s));
  }
  // The rail with its object, then the arm carrying the sensors.
  const double m_sensors = static_cast<double>(spec.sensors.size()) * SensorMassKg(mech, lattice.size());
  std::vector<ScenePart> parts;
  parts.push_back(RailPart(spec));
  parts.push_back(ArmPart(spec, m_sensors, std::move(sensors)));
  return AssembleScene(std::move(root), std::move(parts));
}

}  // namespace tactip
