#pragma once
// The low-friction rail rig (a slider on one vertical slide joint carrying a
// stimulus), the arm that carries the sensor, and scene assembly.

#include <string>
#include <vector>

#include "models/mjcf.h"
#include "models/scene_part.h"
#include "models/skin.h"
#include "sim/config.h"
#include "sim/sim_config.h"

namespace tactip {

/// The object on the rail (the `object.` section).
struct ObjectConfig {
  double mass_kg = 0.1;  ///< slider + stimulus mass

  template <class V>
  void Visit(V& v) {
    v("mass_kg", mass_kg, "kg",
      "Mass of the slider carriage plus stimulus; its weight m g is what friction must hold.",
      Bounds::Closed(1e-3, 50.0));
  }
  void ValidateRules() const {}
};

/// Rail rig and protocol (the `rail.` section).
struct RailConfig {
  /// Deepest indentation a TacTip tolerates, mm (press depth plus its jitter).
  static constexpr double kMaxPressDepthMm = 7.0;
  std::string stimulus = "flat";       ///< flat, acrylic, curved80, curved40, curved20
  double friction_N = 0.005;           ///< rail dry friction (MuJoCo joint frictionloss)
  double damping_Ns_m = 0.02;          ///< rail viscous damping
  double press_depth_mm = 3.0;         ///< indentation at the apex (negative: stops short, no contact)
  double press_depth_jitter_mm = 0.1;  ///< per-run uniform perturbation of the depth
  double approach_gap_mm = 2.0;        ///< initial gap between apex and stimulus
  double press_speed_mm_s = 2.0;       ///< mean speed of the press move
  double lift_mm = 50.0;               ///< lift distance while holding the object
  double lift_speed_mm_s = 25.0;       ///< mean speed of the lift move
  double settle_s = 0.2;               ///< pause before pressing and after the press
  double hold_s = 0.5;                 ///< pause after the lift, before retraction
  double retract_speed_mm_s = 0.1;     ///< retraction speed along the normal
  double retract_speed_max_mm_s = 0.0; ///< > 0: each run's speed drawn from [retract_speed_mm_s, this]
  double post_fall_s = 0.3;            ///< simulated time kept after the object falls

  template <class V>
  void Visit(V& v) {
    v("stimulus", stimulus, "",
      "Stimulus on the slider: flat (10 mm plate), acrylic (the same plate in clear acrylic: the external camera "
      "sees the skin through it), or curved (sphere cap, apex height 20 mm) with radius of curvature 80, 40 or "
      "20 mm.",
      Choices{"flat", "acrylic", "curved80", "curved40", "curved20"});
    v("friction_N", friction_N, "N",
      "Dry friction of the linear rail (recirculating-ball rails: a few mN). Holds the object together "
      "with the skin: slip when mu * sum(N) + friction_N < m g.",
      Bounds::Closed(0.0, 10.0));
    v("damping_Ns_m", damping_Ns_m, "N s/m", "Viscous damping of the rail (lubricant).", Bounds::Closed(0.0, 100.0));
    v("press_depth_mm", press_depth_mm, "mm",
      "Indentation of the dome apex into the stimulus (a TacTip tolerates ~7 mm). Negative: the press stops this "
      "far short of the stimulus and the sensor presses nothing (an empty contact).",
      Bounds::Closed(-kMaxPressDepthMm, kMaxPressDepthMm));
    v("press_depth_jitter_mm", press_depth_jitter_mm, "mm",
      "Per-run variation: depth drawn uniformly in press_depth_mm +- jitter. 0 switches it off.",
      Bounds::Closed(0.0, 2.0));
    v("approach_gap_mm", approach_gap_mm, "mm", "Gap between apex and stimulus at the start (no-contact frames).",
      Bounds::Closed(0.5, 50.0));
    v("press_speed_mm_s", press_speed_mm_s, "mm/s", "Mean speed of the press (smooth quintic profile).",
      Bounds::LeftOpen(0.0, 100.0));
    v("lift_mm", lift_mm, "mm", "Lift while the object is held by friction only (protocol: 50 mm).",
      Bounds::Closed(1.0, 150.0));
    v("lift_speed_mm_s", lift_speed_mm_s, "mm/s", "Mean speed of the lift (smooth quintic profile).",
      Bounds::LeftOpen(0.0, 200.0));
    v("settle_s", settle_s, "s", "Pause at the start and after the press.", Bounds::Closed(0.0, 10.0));
    v("hold_s", hold_s, "s", "Pause after the lift before retraction starts.", Bounds::Closed(0.0, 10.0));
    v("retract_speed_mm_s", retract_speed_mm_s, "mm/s",
      "Retraction speed along the stimulus normal (protocol: 0.1 mm/s offline; 1-20 mm/s online).",
      Bounds::LeftOpen(0.0, 100.0));
    v("retract_speed_max_mm_s", retract_speed_max_mm_s, "mm/s",
      "0: every run retracts at retract_speed_mm_s. Above it: each run draws its speed uniformly from "
      "retract_speed_mm_s to this (the benchmark's mixed set: 0.1 to 5 mm/s); the run's attribute "
      "retract_speed_mm_s holds the drawn speed.",
      Bounds::Closed(0.0, 100.0));
    v("post_fall_s", post_fall_s, "s", "Simulated time kept after the object falls.", Bounds::Closed(0.0, 5.0));
  }
  /// retract_speed_max_mm_s is 0 or at least retract_speed_mm_s.
  void ValidateRules() const;
  /// Radius of curvature of the stimulus in metres (0 = flat).
  double StimulusRadiusM() const;
};

/// The Cartesian arm that carries the sensor (the `arm.` section): two prismatic
/// joints (normal x, vertical z) under stiff position servos.
struct ArmConfig {
  double stage_mass_kg = 0.5;   ///< moving mass of each stage
  double kp_N_m = 1e5;          ///< servo stiffness of each axis
  double damping_ratio = 1.0;   ///< servo damping ratio (joint damping, implicit)

  template <class V>
  void Visit(V& v) {
    v("stage_mass_kg", stage_mass_kg, "kg", "Moving mass of each arm stage.", Bounds::Closed(0.01, 100.0));
    v("kp_N_m", kp_N_m, "N/m",
      "Position-servo stiffness per axis; 1e5 N/m keeps tracking error ~30 um at 3 N contact load.",
      Bounds::Closed(1e2, 1e7));
    v("damping_ratio", damping_ratio, "", "Servo damping ratio (joint damping 2 zeta sqrt(kp m)).",
      Bounds::Closed(0.05, 10.0));
  }
  void ValidateRules() const {}
  /// Servo natural frequency in rad/s for a moving mass.
  double Omega(double moving_mass_kg) const;
};

/// One tactile sensor on the arm (an entry of the `sensors` list): its name and where it sits.
/// The sensors share the arm, the skin design and the cameras' settings; each has its own
/// pins, contacts, noise streams and dataset group.
struct SensorMountConfig {
  /// Longest sensor name.
  static constexpr size_t kMaxNameLength = 32;
  std::string name = "tactip";  ///< prefixes its MJCF elements ("tactip/pin3") and names its dataset group
  double offset_y_mm = 0.0;     ///< sideways offset on the arm, across the rail

  template <class V>
  void Visit(V& v) {
    v("name", name, "",
      "The sensor's name: its dataset group (sensors/NAME/) and the prefix of its MJCF elements (NAME/pin3). "
      "Letters, digits, '_' and '-', starting with a letter.",
      Choices{});
    v("offset_y_mm", offset_y_mm, "mm",
      "Sideways offset of the sensor on the arm, across the rail (y); sensors side by side need at least the "
      "housing's diameter between them. The flat plate widens to stay 25 mm beyond every sensor.",
      Bounds::Closed(-100.0, 100.0));
  }
  /// Throws InputError for a name that is not an identifier (key "sensors.I.name" by `index`).
  void ValidateRules(size_t index) const;
  /// "NAME/": the prefix of the sensor's elements.
  std::string Prefix() const { return name + "/"; }
};

/// Fixed positions of the rig in the world frame (metres).
struct RailLayout {
  static constexpr double kAxisHeight = 0.1;   ///< sensor axis / stimulus centre height at rest
  static constexpr double kApexHeight = 0.02;  ///< curved stimuli protrude 20 mm from their plate
  static constexpr double kRailTravel = 0.2;   ///< slide joint range above the stop
};

/// Names of rig elements.
struct RailNames {
  static constexpr const char* kSlider = "slider";
  static constexpr const char* kSlide = "rail_slide";
  static constexpr const char* kStimulus = "stimulus";
  static constexpr const char* kArmX = "arm_x";
  static constexpr const char* kArmZ = "arm_z";
  static constexpr const char* kServoX = "servo_x";
  static constexpr const char* kServoZ = "servo_z";
  /// The body a sensor is mounted on (its frame is the sensor frame): "NAME/mount".
  static std::string SensorMount(const std::string& sensor) { return sensor + "/mount"; }
};

/// Which pins of a sensor mounted `offset_y_m` sideways can touch the stimulus when pressed
/// to `max_depth_m` (with a 1 mm margin).
std::vector<bool> RailCollidablePins(const SkinConfig& skin, const PinLattice& lattice, const RailConfig& rail,
                                     double max_depth_m, double offset_y_m = 0.0);

/// Parts the rail scene leaves out because no run needs them. Every field false is the lean
/// scene all scenarios simulate; each field set puts one part back, so `tactip bench --lean`
/// can measure what leaving it out saves. None of them is a config key.
struct SceneOptions {
  /// A contact geom on every pin, also on pins that cannot reach the stimulus (in a membrane
  /// lattice those pins then get their normal DOF back too).
  bool all_pins_collide = false;
  /// The purely visual parts: rail beam, sensor housing, the curved stimuli's base plate, light.
  bool visual_geoms = false;
  /// Every pin's outer contact-point site, also without the external camera (without it the
  /// scene has the centre pin's only, which the creep measurement reads).
  bool outer_sites = false;
  /// The object on a free joint instead of the rail's slide joint. A free object has no rail
  /// to hold it against the press, so it is held in place by heavy viscous damping on all six
  /// DOFs (kFreeObjectDampingNs_m) instead of the rail's friction, damping and end stop:
  /// the skin slides over it during the lift. Not the rail protocol's physics; for measuring
  /// the cost of a step only.
  bool object_free_joint = false;
  static constexpr double kFreeObjectDampingNs_m = 1e4;
};

/// Everything a rail scene is built from.
struct RailSceneSpec {
  SimConfig sim;
  ObjectConfig object;
  ContactConfig contact;
  RailConfig rail;
  SkinConfig skin;
  ArmConfig arm;
  std::vector<SensorMountConfig> sensors{SensorMountConfig{}};  ///< the tactile sensors on the arm
  double max_depth_m = 0.0;       ///< deepest press any run will make (for contact culling)
  bool external_markers = false;  ///< the external camera records every pin's outer contact point
  SceneOptions options;           ///< parts put back that the runs do not need (default: none)
};

/// Which pins carry an outer contact-point site: all with the external camera (or
/// options.outer_sites), else the centre pin only.
std::vector<bool> RailOuterSitePins(const RailSceneSpec& spec, size_t n_pins);

/// Moving mass of one sensor carried by the arm's z stage: housing plus skin (kg).
double SensorMassKg(const SkinMechanics& mech, size_t n_pins);

/// Assembles the rail scene from its parts: the rail with the slider and its stimulus (the
/// object), the arm with its servos carrying a mount and skin per sensor; only what
/// spec.options puts back beyond what the runs need.
BuiltScene BuildRailScene(const RailSceneSpec& spec);

/// Initial arm x offset: the dome centre's world x when the apex is `gap_m` from the
/// stimulus apex (the stimulus apex plane is world x = 0).
double SensorCentreX(const SkinConfig& skin, double gap_m);

}  // namespace tactip
