#pragma once
// The TacTip skin as a pin lattice: geometry of the pins on the dome, the mechanical
// parameters derived from materials, and the MJCF part that carries them.

#include <algorithm>
#include <array>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "models/mjcf.h"
#include "sim/config.h"

namespace tactip {

/// The range of skin.skin_modulus_mpa: from a soft silicone gel's few kPa to a stiff rubber's.
inline constexpr double kSkinModulusMinMpa = 0.001;
inline constexpr double kSkinModulusMaxMpa = 100.0;

/// Skin geometry and materials (the `skin.` section). Stiffnesses are derived from
/// these values by SkinMechanics, never set directly.
struct SkinConfig {
  double radius_mm = 20.0;          ///< outer dome radius
  double pitch_mm = 3.0;            ///< pin spacing on the hexagonal lattice (arc length)
  int rings = 6;                    ///< hexagonal rings around the centre pin (6 -> 127 pins)
  double thickness_mm = 1.0;        ///< skin thickness
  double pin_length_mm = 1.5;       ///< how far a pin reaches inwards from the skin's inner surface
  double pin_mass_g = 0.2;          ///< moving mass per pin (pin plus its gel column)
  double gel_modulus_kpa = 100.0;   ///< Young's modulus of the gel filling
  double gel_depth_mm = 20.0;       ///< depth of the gel column under each pin
  double gel_shear_modulus_kpa = 10.0; ///< shear modulus of the gel under the pins (0 = gel_modulus_kpa / 3)
  double skin_modulus_mpa = 1.0;    ///< Young's modulus of the skin rubber
  double damping_ratio = 0.7;       ///< damping ratio of each pin's normal mode
  double shear_damping_ratio = 4.0; ///< damping ratio of the skin's in-plane (shear) mode
  std::string shell_damping = "viscous"; ///< shell skin: viscous (fixed damper) or gel (follows the carried mass)
  double gel_loss_tangent = 0.16;   ///< shell_damping = gel: the gel's loss tangent in shear
  double contact_radius_mm = 1.5;   ///< radius of the spherical contact patch at each pin
  std::string coupling = "shell";   ///< how pins are coupled through the skin: shell, membrane or none
  std::string rim = "free";         ///< the skin beyond the pattern: free, or clamped at the dome's base
  std::string membrane_links = "isotropic"; ///< membrane lattice: links pull on both in-plane components, or along themselves
  std::string normal_spring = "axial";  ///< lattice pins' gel springs: rest point fixed (axial) or sliding over the dome (dome)
  std::string pattern = "smooth";   ///< smooth, fingerprint-v1, fingerprint-v2
  double ridge_spacing_mm = 3.0;    ///< fingerprint: radial step between ridge rings (arc length)
  double ridge_height_mm = 2.0;     ///< fingerprint: ridge height above the skin (v2: peak-to-trough)
  std::string ridge_shape = "sine"; ///< fingerprint: square (raised rings) or sine (continuous wave)
  std::string ridge_rocking = "winkler"; ///< fingerprint: the gel under a rocking ridge: winkler columns or a half-space
  int pins_per_ring = 6;            ///< fingerprint: ring k carries pins_per_ring * k pins
  double pattern_radius_mm = 20.0;  ///< fingerprint: arc radius of the outermost ring allowed
  std::string marker_model = "gel"; ///< what moves the markers: gel (pins plus the gel's lateral flow) or pins
  double gel_flow_depth_mm = 2.5;   ///< gel field: depth of the gel layer that carries the lateral flow
  double gel_squeeze_mm = 0.5;      ///< gel field: indentation at which a pin's sideways squeeze saturates

  template <class V>
  void Visit(V& v) {
    v("radius_mm", radius_mm, "mm", "Outer radius of the hemispherical dome (TacTip: 40 mm diameter).",
      Bounds::Closed(5.0, 100.0));
    v("pitch_mm", pitch_mm, "mm", "Pin spacing on the hexagonal lattice, measured along the dome (TacTip: 3 mm).",
      Bounds::Closed(0.5, 20.0));
    v("rings", rings, "",
      "Hexagonal rings around the centre pin; N = 1 + 3 r (r + 1) pins (6 -> 127). At least 1: a lone centre pin "
      "has no skin around it to carry.",
      Bounds::Closed(1, 12));
    v("thickness_mm", thickness_mm, "mm",
      "Skin thickness. Sets the bending coupling between neighbouring pins, D = E t^3 / (12 (1 - nu^2)).",
      Bounds::Closed(0.1, 5.0));
    v("pin_length_mm", pin_length_mm, "mm",
      "Length of each pin inwards from the skin's inner surface; the camera sees the inner end.",
      Bounds::Closed(0.0, 10.0));
    v("pin_mass_g", pin_mass_g, "g",
      "Moving mass per pin: the pin plus its share of gel (gel ~1 g/cm^3 x 7.8 mm^2 cell x 20 mm ~ 0.16 g). "
      "Larger values slow the pin mode (omega = sqrt(k/m)) and allow a larger timestep.",
      Bounds::Closed(0.01, 100.0));
    v("gel_modulus_kpa", gel_modulus_kpa, "kPa",
      "Young's modulus of the gel. Each pin rests on a gel column: k_normal = E A_cell / h_gel, "
      "k_shear = (E/3) A_cell / h_gel (incompressible gel). 100 kPa gives ~2.6 N at 3 mm indentation.",
      Bounds::Closed(1.0, 10000.0));
    v("gel_depth_mm", gel_depth_mm, "mm", "Height of the gel column under each pin (about the dome radius).",
      Bounds::Closed(1.0, 100.0));
    v("gel_shear_modulus_kpa", gel_shear_modulus_kpa, "kPa",
      "Shear modulus G of the gel the skin slides on: each pin's shear column k_shear = G A_cell / h_gel (the "
      "smooth skin's shell carries all pins' columns in parallel: 127 x 3.9 = 495 N/m at 10 kPa, ~2 mm of shear "
      "per newton). gel_modulus_kpa is a lumped normal stiffness fitted to force against depth (it carries the "
      "skin's tension and the confined gel too); a silicone gel's own shear modulus is several times lower than "
      "gel_modulus_kpa / 3. 10 (the default, the smooth skin's shell): calibrated to the real TacTip's gross-slip "
      "spike (~20 frames of above-noise pin motion from the onset), which the shell meets at 11 kPa and below "
      "and misses at 13 (README 'The smooth skin's shear'); the fingerprint presets, whose membrane lattice resolves the skin, set 6.67 "
      "(README 'The skin's materials'). 0: gel_modulus_kpa / 3, the column's own modulus taken as an "
      "incompressible solid (the smooth shell before the calibration, 1650 N/m).",
      Bounds::Closed(0.0, 10000.0));
    v("skin_modulus_mpa", skin_modulus_mpa, "MPa",
      "Young's modulus of the skin rubber (Shore A 26-28 -> ~1 MPa by Gent's relation; the fingerprint presets "
      "set a fitted 0.4 MPa, README 'The skin's materials').",
      Bounds::Closed(kSkinModulusMinMpa, kSkinModulusMaxMpa));
    v("damping_ratio", damping_ratio, "",
      "Damping ratio of each pin's normal mode (gel viscosity); joint damping 2 zeta sqrt(k m), "
      "integrated implicitly.",
      Bounds::Closed(0.0, 10.0));
    v("shear_damping_ratio", shear_damping_ratio, "",
      "Damping ratio of each pin's own shear mode in the lattices (coupling membrane or none), and of the shell "
      "skin's in-plane mode under shell_damping = viscous (4 -> released shear relaxes with a ~58 ms time constant).",
      Bounds::Closed(0.0, 20.0));
    v("shell_damping", shell_damping, "",
      "How the shell skin's in-plane damper is set (coupling shell; the lattices damp each pin by "
      "shear_damping_ratio and ignore this). viscous: one fixed damper giving the shell alone "
      "shear_damping_ratio. gel: a gel with a constant loss tangent, gel_loss_tangent, so every mode the shell "
      "forms has a damping ratio of half of it: the damper along the rail follows the mass the shell carries - "
      "its own, plus the held object's share while its contacts stick (rail and incipient scenarios); released "
      "shear rings on after gross slip. A shell damped below a ratio of 0.5 is validated with a sliding step "
      "(sim.sliding_timestep_s, from the gross-slip onset on) up to 0.001 s (README 'The pin-lattice skin').",
      Choices{"viscous", "gel"});
    v("gel_loss_tangent", gel_loss_tangent, "",
      "Loss tangent tan(delta) = G''/G' of the gel's shear modulus (shell_damping = gel): the shell's in-plane "
      "modes are damped at a ratio tan(delta) / 2. Soft silicone gels have 0.05-0.3 at 1-100 Hz; 0.16 (ratio "
      "0.08) lies mid-range (README 'Slip signatures against the hardware' gives the gross-slip spike it "
      "makes).",
      Bounds::Closed(0.01, 2.0));
    v("contact_radius_mm", contact_radius_mm, "mm",
      "Radius of the spherical contact patch at each pin; half the pitch so neighbouring patches touch.",
      Bounds::Closed(0.1, 10.0));
    v("coupling", coupling, "",
      "shell: the membrane is rigid in-plane (one shell on the gel carries all pins tangentially; bending "
      "springs couple neighbours' normal motion) - the smooth TacTip. membrane: every pin has its own two shear "
      "DOFs, coupled to its neighbours by membrane springs (E t) in series with the ridges' rocking compliance - "
      "the fingerprint skins, which show partial slip. none: every pin on its own gel column, no coupling - the "
      "brush model, used to validate the contact mechanics.",
      Choices{"shell", "membrane", "none"});
    v("rim", rim, "",
      "The skin beyond the pin pattern. free: not modelled; the pattern's in-plane motion is held by the gel "
      "alone (the smooth skin's lumped shell). clamped (the fingerprint presets): the skin rubber from the pattern's edge (outermost ring plus half a step) to the dome's "
      "base (arc pi R / 2), where the skin is clamped to the sensor, is a flat annular membrane (E t, Poisson "
      "1/3 as the lattice's network) that pulls a translated pattern back with K = 2 pi mu t (1 + kappa) / "
      "(kappa ln(b/a) - (b^2 - a^2) / (kappa (a^2 + b^2))), kappa = (3 - nu) / (1 + nu): added to the shell's "
      "shear springs (shell) or shared by the outermost ring's pins (membrane). See README 'The skin's rim'.",
      Choices{"free", "clamped"});
    v("membrane_links", membrane_links, "",
      "How a membrane lattice's link (coupling membrane; the shell and none ignore this) pulls on its two pins' "
      "contact points. isotropic: on both in-plane components, k_couple = link in series with two ridges. "
      "central: along the link only, as the triangular spring network that k_link = (sqrt 3 / 2) E t is derived "
      "from; a ridge rocks only across itself, so the ridges enter by the link's radial share c: k = 1 / (1 / "
      "k_link + 2 c^2 / k_rock), which is k_couple for a radial link, k_link along a ring. At a step of 0.25 ms "
      "or finer it puts v2's first slip on the east/west sides in most runs at 0.1-0.5 mm/s (README 'Membrane "
      "links'); opt-in. 'validate contact' judges it against its exact quasi-static solution on central links "
      "(README 'Contact validation'). orthotropic: the skin between the pins as linear triangles of a corrugated "
      "sheet - the concentric ridges make it radially soft (stretched across its waves it bends, compliance "
      "1 + 6 (1 - nu^2) (a / t)^2, a half the ridge height) and hoop stiff (the developed length), shear "
      "carried along the developed path - scaled by k_couple / k_link for the ridges' rocking; fingerprint "
      "patterns only; opt-in; 'validate contact' judges it against its exact solution too (README 'Orthotropic "
      "membrane').",
      Choices{"isotropic", "central", "orthotropic"});
    v("normal_spring", normal_spring, "",
      "Where each lattice pin's normal (gel column) spring rests once the pin shears (coupling membrane or none; "
      "the shell ignores this). axial: at the pin's rest height along the sensor axis, so a pin sheared in the "
      "sensor's y-z plane leaves the dome without loading its column. dome: on the dome - a shear (u_y, u_z) "
      "moves the rest point by -(n_y u_y + n_z u_z) / n_x along the axis (n: the pin's dome normal; one fixed "
      "tendon per pin over its three joints, stiffness k_n), so a pin slides freely over the dome's surface and "
      "one sheared away from the apex recedes from the stimulus by tan(theta) of its shear: the object's weight "
      "unloads the contact's lower (south) side and loads its upper side. The gel field then reads the spring's "
      "compression. Along the dome normal the spring is k_n / cos^2(theta): the pin normal mode's bound takes "
      "the lattice's widest pin, and the shear joints take that mode's damping floor too (README 'Dome "
      "springs'). Opt-in; refused on fingerprint-v1 (its edge pins flicker in and out of contact while held) "
      "and by 'validate contact' and 'accuracy domes' (their exact solution has axial springs).",
      Choices{"axial", "dome"});
    v("pattern", pattern, "",
      "Outer skin pattern. smooth: hexagonal pin lattice (pitch_mm, rings). fingerprint-v1: concentric raised "
      "ridge rings with the pins extending into them (they pivot: the inner marker and the outer contact point "
      "move differently). fingerprint-v2: a continuous circular wave with the pins running through the skin at "
      "its peaks (inner and outer markers move together). Fingerprint pins sit on rings ridge_spacing_mm apart. "
      "'--skin NAME' on the command line applies the documented preset of the variant.",
      Choices{"smooth", "fingerprint-v1", "fingerprint-v2"});
    v("ridge_spacing_mm", ridge_spacing_mm, "mm",
      "Fingerprint: radial step between ridge rings along the dome (v1: 4 mm, v2: 3 mm). Sets the pin count, "
      "each pin's gel cell, and the ridge base width (half the spacing).",
      Bounds::Closed(1.0, 10.0));
    v("ridge_height_mm", ridge_height_mm, "mm",
      "Fingerprint: height of the ridges above the skin (v1: 2 mm; v2: 2 mm peak-to-trough). Raises the contact "
      "surface and sets the lever of the ridges' rocking compliance (k_rock = k_theta / lever^2).",
      Bounds::Closed(0.1, 10.0));
    v("ridge_shape", ridge_shape, "",
      "Fingerprint: square ridges (v1) rock about their root, lever = ridge height; a sine wave (v2) rocks about "
      "its mid-height, lever = half the height.",
      Choices{"square", "sine"});
    v("ridge_rocking", ridge_rocking, "",
      "Fingerprint: what the gel under a ridge's base (width w = ridge_spacing_mm / 2, length b per pin) gives "
      "against its rocking, besides the skin hinges in the valleys. winkler: the gel columns of depth gel_depth_mm, "
      "k_theta = (E_gel / h_gel) b w^3 / 12. half-space: a rigid strip rocking on an incompressible elastic "
      "half-space of the same Young's modulus, k_theta = pi E* b w^2 / 16, E* = E_gel / (1 - 0.5^2) (plane "
      "strain). A base a tenth as wide as the gel is deep loads only the gel near it, which columns of the full "
      "depth make pi h_gel / w times too soft (31 on v1, 42 on v2): with the skin hinges, v1's ridges rock 12 "
      "times stiffer (k_rock 9.3 -> 115 N/m), v2's twice (191 -> 371 N/m). Opt-in; README 'Ridge rocking' gives "
      "the figures it moves.",
      Choices{"winkler", "half-space"});
    v("pins_per_ring", pins_per_ring, "", "Fingerprint: ring k (k >= 1) carries pins_per_ring * k pins.",
      Bounds::Closed(1, 24));
    v("pattern_radius_mm", pattern_radius_mm, "mm",
      "Fingerprint: arc radius of the outermost ring; rings sit at k * ridge_spacing_mm <= this.",
      Bounds::Closed(1.0, 60.0));
    v("marker_model", marker_model, "",
      "What moves the markers the cameras see. gel: each pin's body (MuJoCo) plus the gel's lateral flow - an "
      "indented pin squeezes the incompressible gel sideways and the flow carries every marker outwards, so a "
      "press moves all markers, the outer ring too, as on a real TacTip. pins: the pin bodies alone (the contact "
      "dynamics are the same; only the markers differ). See README 'Marker kinematics: the gel field'.",
      Choices{"gel", "pins"});
    v("gel_flow_depth_mm", gel_flow_depth_mm, "mm",
      "Gel field: depth of the gel layer under the skin that flows sideways with it (a squeezed volume V moves "
      "the skin by V / (2 pi h s) at distance s). 2.5 mm, with gel_squeeze_mm 0.5, puts a flat press's marker "
      "field within a factor 1.5 of a real 127-pin TacTip's at 2-4 mm (README).",
      Bounds::Closed(0.1, 50.0));
    v("gel_squeeze_mm", gel_squeeze_mm, "mm",
      "Gel field: a pin indented by w squeezes a gel volume h tanh(w / h) per unit cell area sideways, h this "
      "value; deeper indentation pushes the gel column towards the core instead. 0.5 mm gives the real TacTip's "
      "steep rise by 1 mm and slow growth after (README).",
      Bounds::Closed(0.01, 5.0));
  }
  /// The gel's shear modulus in Pa: gel_shear_modulus_kpa, or gel_modulus_kpa / 3 when that is 0.
  double GelShearModulusPa() const;
  /// Damping ratio of the shell skin's in-plane mode: gel_loss_tangent / 2 under shell_damping = gel,
  /// else shear_damping_ratio.
  double ShellDampingRatio() const { return shell_damping == "gel" ? 0.5 * gel_loss_tangent : shear_damping_ratio; }
  /// Radius of the contact surface: the dome plus the ridges of a fingerprint pattern.
  double OuterRadiusMm() const;
  /// Radius of each pin's spherical contact patch (fingerprint: at most half the ring step).
  double ContactRadiusMm() const;
  /// True for the fingerprint patterns.
  bool Fingerprint() const { return pattern != "smooth"; }
  /// Lattice pins whose gel springs rest on the dome (skin.normal_spring = dome; the shell has none).
  bool DomeSprings() const { return normal_spring == "dome" && coupling != "shell"; }
  /// Radial step between pin rings along the dome: ridge_spacing_mm (fingerprint) or pitch_mm.
  double RingStepMm() const { return Fingerprint() ? ridge_spacing_mm : pitch_mm; }
  /// Arc length from the apex to the dome's base, where the skin is clamped: pi R / 2.
  double BaseArcMm() const { return 0.5 * std::numbers::pi * radius_mm; }
  /// Cross-field rules (the lattice must fit on the hemisphere).
  void ValidateRules() const;
};

/// Contact properties of the skin (the `contact.` section).
struct ContactConfig {
  double friction = 1.0;            ///< static Coulomb coefficient skin-stimulus
  double kinetic_ratio = 0.6;       ///< kinetic / static friction coefficient
  double friction_jitter = 0.05;    ///< per-run relative perturbation of the friction (uniform +-)
  double pin_friction_spread = 0.0; ///< per-pin relative perturbation of the friction (uniform +-)
  double weakening_speed_mm_s = 0.0;///< velocity-weakening scale v_c (0 = switch at the slip tolerance)
  double breakaway_ratio = 1.0;     ///< coefficient right after breakaway / static (weakening from there)
  double slip_memory_um = 0.0;      ///< slip distance over which a pin's friction follows its speed (0 = at once)
  double timeconst_s = 0.004;       ///< contact softness time constant
  double impedance = 0.99;          ///< contact impedance d (solimp dmax), closer to 1 = harder
  double impedance_min = 0.5;       ///< impedance at zero penetration (solimp dmin)
  double impedance_width_mm = 0.02; ///< penetration over which the impedance rises to `impedance` (solimp width)
  double presliding_mm = 0.01;      ///< tangential give of a sticking contact at the Coulomb limit (sim.noslip = exact)

  template <class V>
  void Visit(V& v) {
    v("friction", friction, "",
      "Static Coulomb friction coefficient between skin and stimulus (silicone rubber on PLA/acrylic "
      "~0.5-1.5).",
      Bounds::Closed(0.01, 5.0));
    v("kinetic_ratio", kinetic_ratio, "",
      "Kinetic over static friction (silicone rubber on smooth plastics ~0.5-0.8). A sliding pin's coefficient "
      "drops to kinetic_ratio * friction until it sticks again, so slip starts with the sudden release seen "
      "on hardware; 1 gives pure single-coefficient Coulomb friction.",
      Bounds::LeftOpen(0.0, 1.0));
    v("friction_jitter", friction_jitter, "",
      "Per-run variation: friction is drawn uniformly in friction * (1 +- jitter). 0 switches it off.",
      Bounds::RightOpen(0.0, 1.0));
    v("pin_friction_spread", pin_friction_spread, "",
      "Per-pin variation within a run (surface roughness, moulding): pin i's coefficients are scaled by "
      "(1 + spread * u_i), u_i uniform in [-1, 1), drawn per run. 0 gives every pin the same friction.",
      Bounds::RightOpen(0.0, 0.5));
    v("weakening_speed_mm_s", weakening_speed_mm_s, "mm/s",
      "Velocity weakening: a pin sliding at speed v has mu_k + (mu_s - mu_k) / (1 + v / v_c). 0 switches a pin "
      "to mu_k as soon as it slides faster than labels.slip_speed_m_s.",
      Bounds::Closed(0.0, 1000.0));
    v("breakaway_ratio", breakaway_ratio, "",
      "With velocity weakening: a pin that breaks away (starts to slide) drops at once to breakaway_ratio * "
      "friction and weakens from there, mu_k + (mu_b - mu_k) / (1 + v / v_c); a pin that is not sliding weakens "
      "from the static value. 1 = no sudden drop (the weakening is continuous from rest). Between "
      "kinetic_ratio and 1.",
      Bounds::LeftOpen(0.0, 1.0));
    v("slip_memory_um", slip_memory_um, "um",
      "With velocity weakening: a pin's coefficient follows the weakened value of its slip speed over this slip "
      "distance D_c instead of at once, mu <- mu_v + (mu - mu_v) exp(-v dt / D_c) each step (the slip law of "
      "rate-and-state friction): a contact must slide D_c to lose its friction, which removes the law's "
      "instantaneous negative damping; a breakaway drop is spread over D_c too. A pin that leaves contact starts "
      "again from the static value; one that sticks again regains its friction only as it creeps (over D_c of "
      "creep), not with time. 0 = memoryless.",
      Bounds::Closed(0.0, 1000.0));
    v("timeconst_s", timeconst_s, "s",
      "MuJoCo contact time constant (solref). Must be >= 2 timesteps; with impedance 0.99 the contact "
      "is ~30x stiffer than a pin's gel spring, so the gel, not the solver, sets the indentation.",
      Bounds::Closed(1e-4, 0.1));
    v("impedance", impedance, "",
      "MuJoCo contact impedance d in (0,1) once the contact has penetrated impedance_width_mm (solimp dmax); "
      "steady penetration scales with (1-d)/d.",
      Bounds::Closed(0.5, 0.9999));
    v("impedance_min", impedance_min, "",
      "Contact impedance at zero penetration (solimp dmin). Contacts are found at the start of a step, so a pin "
      "that loses contact for one step is launched by its preload; a soft onset keeps the contact's stiffness at "
      "touch-down within the step's reach (contact mode omega_0 dt < 2, see 'Numerical stability').",
      Bounds::Closed(0.01, 0.9999));
    v("impedance_width_mm", impedance_width_mm, "mm",
      "Penetration over which the impedance rises from impedance_min to impedance (solimp width). Small against "
      "the loaded pins' penetration (~35 um), so they sit at the full impedance.",
      Bounds::Closed(1e-4, 1.0));
    v("presliding_mm", presliding_mm, "mm",
      "Pre-sliding displacement: a sticking contact gives elastically along its surface and reaches the Coulomb "
      "limit mu N at this displacement (tangential stiffness mu N / presliding, so every contact's friction "
      "is used in proportion to its normal force). Lets a contact compress along a sloped surface without "
      "sliding. 0 = rigid stick. Used by the friction pass (sim.noslip = exact).",
      Bounds::Closed(0.0, 1.0));
  }
  /// impedance_min must not exceed impedance.
  void ValidateRules() const;
  /// The MJCF solimp vector of a contact geom.
  std::vector<double> Solimp() const {
    return {impedance_min, impedance, impedance_width_mm * 1e-3, 0.5, 2.0};
  }
  /// Velocity-weakened coefficient of a pin with static coefficient mu_s slipping at
  /// slip_speed_m_s (needs weakening_speed_mm_s > 0): kinetic_ratio * mu_s when fast;
  /// towards rest, mu_s for a pin that is not sliding and breakaway_ratio * mu_s for one
  /// that has broken away; halfway at the weakening speed.
  double WeakenedFriction(double mu_s, double slip_speed_m_s, bool broken_away = false) const {
    const double mu_k = kinetic_ratio * mu_s;
    const double mu_0 = broken_away ? std::max(mu_k, breakaway_ratio * mu_s) : mu_s;
    return mu_k + (mu_0 - mu_k) / (1.0 + slip_speed_m_s / (weakening_speed_mm_s * 1e-3));
  }
};

/// One pin of the lattice in the sensor frame (x = dome axis, outwards; z = up).
struct PinGeometry {
  int index = 0;                        ///< 0 = centre pin
  int ring = 0;                         ///< hexagonal ring (0 = centre)
  double polar_rad = 0.0;               ///< angle from the dome axis
  double azimuth_rad = 0.0;             ///< angle around the axis, from +y towards +z
  std::array<double, 3> normal{};       ///< outward unit normal of the dome at the pin
};

/// Pin positions and neighbour pairs of a hexagonal lattice wrapped on the dome
/// (azimuthal-equidistant: arc length from the apex = planar distance).
struct PinLattice {
  std::vector<PinGeometry> pins;                ///< ordered by ring, then azimuth
  std::vector<std::array<int, 2>> neighbours;   ///< lattice edges (i < j)

  /// Builds the lattice; throws InputError if it does not fit on the hemisphere.
  static PinLattice Build(const SkinConfig& skin);
  size_t size() const { return pins.size(); }
};

/// The concentric ridges make a fingerprint skin a corrugated sheet (README 'Orthotropic
/// membrane'; flat for the smooth skin).
struct Corrugation {
  /// Radial compliance over the flat sheet's: stretched across its waves the sheet bends as
  /// well as stretches, 1 + 6 (1 - nu^2) (a / t)^2, a the waves' amplitude (half the ridge height).
  double radial_factor = 1.0;
  /// Developed over projected length of one ridge period: the hoop direction has that much more
  /// rubber per unit width, in-plane shear runs that much longer a path.
  double length_ratio = 1.0;
  static Corrugation Of(const SkinConfig& skin);
};

/// Spring constants and masses derived from SkinConfig (SI units).
struct SkinMechanics {
  /// A membrane lattice's damping floor keeps each mode's stable step this many times above
  /// the timestep (NormalDamping, TipDamping).
  static constexpr double kDampingRaiseMargin = 1.2;
  double cell_area_m2 = 0.0;        ///< hexagonal cell area per pin
  double k_normal_N_m = 0.0;        ///< gel column, along the pin normal
  double k_shear_N_m = 0.0;         ///< gel column, in shear (per pin)
  double k_bend_N_m = 0.0;          ///< skin bending coupling between neighbours' normal motion
  double pin_mass_kg = 0.0;
  double shell_mass_kg = 0.0;       ///< skin membrane mass
  double shell_moving_mass_kg = 0.0;  ///< what the shell's in-plane joints carry: membrane plus every pin
  double pin_damping_Ns_m = 0.0;    ///< normal-mode damping per pin
  double shell_damping_Ns_m = 0.0;  ///< damping of the skin's in-plane translation
  double membrane_N_m = 0.0;        ///< in-plane membrane stiffness E t (reported, see README)
  Corrugation corrugation;          ///< the ridges' corrugation of the membrane (orthotropic links)
  double dome_radius_m = 0.0;       ///< the core's radius (the lattice's arc-length layout)
  // Per-pin shear DOFs (coupling membrane or none):
  double k_rock_N_m = 0.0;          ///< ridge rocking stiffness at the contact point (0: no ridges)
  double k_tip_N_m = 0.0;           ///< contact point to base in shear: gel in series with the ridge
  double k_link_N_m = 0.0;          ///< membrane spring between neighbouring pins, (sqrt 3 / 2) E t
  double k_couple_N_m = 0.0;        ///< neighbour coupling of the contact points: link in series with two ridges
  double tip_damping_Ns_m = 0.0;    ///< shear damping per pin DOF
  double marker_rock_factor = 0.0;  ///< inner marker = contact point - this * ridge deflection
  int max_degree = 6;               ///< most neighbours of any pin
  bool central_links = false;       ///< membrane lattice: links act along themselves (skin.membrane_links)
  double central_row_max_N_m = 0.0; ///< central links: widest row sum of the shear stiffness matrix (From(skin, lattice))
  bool orthotropic_links = false;   ///< membrane lattice: the corrugated sheet's triangles (skin.membrane_links)
  double orthotropic_row_max_N_m = 0.0;  ///< orthotropic: widest row sum, by magnitude, of the membrane's shear stiffness
  /// skin.normal_spring = dome on a lattice with per-pin shear DOFs (From(skin, lattice);
  /// else 1 and 0): 1 / cos^2 of the lattice's widest pin, its spring along the dome normal
  /// over k_n; and the widest shear-joint row of one pin's spring, k_n |a| (1 + |a| + |b|)
  /// with a, b = n_y / n_x, n_z / n_x.
  double dome_gain = 1.0;
  double dome_shear_row_N_m = 0.0;
  // The clamped rim (skin.rim = clamped; set by From(skin, lattice), else zero):
  double k_rim_N_m = 0.0;           ///< the skin annulus against a translation of the whole pattern (RimAnchor)
  double k_rim_pin_N_m = 0.0;       ///< membrane lattice: an outer-ring pin's share, in series with its ridge
  int rim_ring = -1;                ///< the ring the annulus holds (-1: none)

  static SkinMechanics From(const SkinConfig& skin, size_t n_pins);
  /// With the lattice: the neighbour count enters the stiffest shear mode.
  static SkinMechanics From(const SkinConfig& skin, const struct PinLattice& lattice);
  /// Highest natural frequency of the pin lattice (rad/s): normal mode with every
  /// neighbour in antiphase, omega = sqrt((k_n dome_gain + 12 k_b) / m).
  double StiffestOmega() const;
  /// The smooth skin's shell against an in-plane translation: its n_pins gel columns in
  /// parallel, plus the clamped rim.
  double ShellShearStiffness(size_t n_pins) const { return static_cast<double>(n_pins) * k_shear_N_m + k_rim_N_m; }
  /// A pin's own shear stiffness (membrane or uncoupled lattice): k_tip, plus its share of the
  /// clamped rim on the outermost ring.
  double TipStiffness(int ring) const { return ring == rim_ring ? k_tip_N_m + k_rim_pin_N_m : k_tip_N_m; }
  /// Highest shear-mode frequency of a membrane lattice (Gershgorin bound, with the dome
  /// springs' shear rows), rad/s.
  double StiffestShearOmega() const;
  /// A central link's stiffness along itself (skin.membrane_links = central), N/m: the
  /// membrane spring in series with the two ridges' rocking, which takes the link's radial
  /// share `radial_share` (cosine between the link and the radial direction, 0..1).
  double CentralLinkStiffness(double radial_share) const;
  /// A central link between two pins: its unit direction (y, z) in the sensor's plane and its
  /// stiffness along it.
  struct CentralLink {
    double ey = 0.0, ez = 0.0, k_N_m = 0.0;
  };
  CentralLink CentralLinkBetween(const PinGeometry& a, const PinGeometry& b) const;
  /// Shear damping per pin DOF of a membrane/uncoupled lattice at this timestep: the
  /// physical value (shear_damping_ratio on k_tip), raised where the stiffest shear mode
  /// would otherwise be unstable (tendon springs are integrated explicitly).
  double TipDamping(double timestep_s) const;
  /// Normal damping per pin of a membrane lattice at this timestep: the physical value
  /// (damping_ratio on k_normal), raised where the stiffest bending-coupled normal mode
  /// would otherwise be unstable. With dome springs TipDamping takes the same floor.
  double NormalDamping(double timestep_s) const;
  /// The damping a dome spring's own coordinate L sees through its joints' implicit
  /// dampers (normal c_normal, shear c_tip) at the widest pin: 1 / (1 / c_n + (g - 1) / c_t),
  /// g = dome_gain, against the mass m / g; c_normal without dome springs. With both dampers at
  /// the floor c it is c / g, which is the floor for that mass.
  double DomeSpringDamping(double c_normal, double c_tip) const;
};

/// The skin keys of the `--skin NAME` presets: "skin.key=value" overrides for smooth,
/// fingerprint-v1 and fingerprint-v2 (throws InputError for another name). The fingerprint
/// presets carry the membrane lattice's resolved materials (a gel of 6.67 kPa in shear, a
/// 0.4 MPa skin, the rim clamped); the smooth skin keeps the defaults.
std::vector<std::string> SkinPreset(const std::string& name);

/// Largest step at which a skin with per-pin shear DOFs is validated at mu = 1, s (see
/// ShearDofValidatedTimestep in models/stability.h).
inline constexpr double kShearDofValidatedStepS = 0.001;

/// A shell skin whose in-plane mode is damped below this ratio (SkinConfig::ShellDampingRatio)
/// rings after its release, and is validated with a sliding step up to kLightShellValidatedStepS only.
inline constexpr double kLightShellDampingRatio = 0.5;

/// Largest sliding step (from the gross-slip onset on) at which a lightly damped shell skin is
/// validated, s; its held phase takes the default 2 ms (gel 0.08, flat at 0.1 and 1 mm/s and the
/// four held-phase scenes: healthy, onsets within 3 ms of 1 ms throughout). At 2 ms the released
/// shell's ringing makes the sliding contacts chatter during gross slip (the total normal force
/// of the flat press at 1 mm/s falls to 0.04 of its value at the onset with 6 of 19 pins in
/// contact under the gel's 0.08, to 0.50 with 12 of 19 under a fixed damper at 0.1, to 0.69 with
/// 13 at 0.3; at 0.5 and above it stays at 0.81 or more with all 19). At 1 ms it stays at 0.92
/// (gel 0.08) and 0.94 (fixed 0.1) with all 19 (README, The pin-lattice skin).
inline constexpr double kLightShellValidatedStepS = 0.001;

/// The step the fingerprint-v2 preset sets, s. At the 1 ms validated step v2's edge contacts
/// lift off and touch the object again as the ridges let go in turn (9 of 10 incipient runs
/// flagged by run health, one pin at 0.02-55 mN); at 0.5 ms 1 of 10 (0.02 mN), and the gross
/// onsets of those ten runs lie 0.08 s (mean) from the 0.25 ms ones against 0.19 s at 1 ms
/// (README, Numerical stability).
inline constexpr double kFingerprintV2StepS = 0.0005;

/// The step `--skin NAME` sets: none for the smooth skin (the scene's default), the validated
/// step kShearDofValidatedStepS for fingerprint-v1, kFingerprintV2StepS for fingerprint-v2.
std::optional<double> SkinPresetTimestep(const std::string& name);

/// What `--skin NAME` sets in a scene's config: SkinPreset and, for a fingerprint skin (per-pin
/// shear DOFs), its step sim.timestep_s = SkinPresetTimestep(name).
std::vector<std::string> SkinPresetOverrides(const std::string& name);

/// Names of a skin's elements in the MJCF, so scenarios can look the parts up. Every name
/// starts with `prefix`: the sensor's name and '/' in a scene of named sensors ("left/pin3"),
/// "" in a scene of one skin.
struct SkinNames {
  std::string prefix;

  std::string PinBody(int i) const;
  std::string PinJoint(int i) const;
  std::string PinShearJoint(int i, char axis) const;  ///< uncoupled skin: 'y' or 'z' shear DOF
  std::string PinDomeSpring(int i) const;  ///< skin.normal_spring = dome: the pin's gel spring (a fixed tendon)
  std::string PinGeom(int i) const;
  std::string PinSite(int i) const;       ///< inner end of the pin (what the camera sees)
  std::string PinOuterSite(int i) const;  ///< outer contact point (external markers)
  std::string Shell() const { return prefix + "skin_shell"; }
  /// Any other element of the skin (shell joints, tendons): `prefix` + `name`.
  std::string Part(const std::string& name) const { return prefix + name; }
};

/// The MJCF part of a skin: a body subtree to hang under the sensor mount, tendons,
/// and which pins carry a collision geom.
struct SkinPart {
  mjcf::Element body{"body"};
  std::vector<mjcf::Element> tendons;
  std::vector<bool> collidable;  ///< per pin
  int n_collidable = 0;
};

/// Builds the skin part (skin.coupling chooses the shell, membrane or uncoupled lattice). `collidable[i]` says whether pin i gets a contact
/// geom (pins that cannot touch the stimulus get none; in a membrane lattice they also get
/// no DOFs: the skin beyond the contact anchors its neighbours). Contact bits: pins have
/// contype 0 / conaffinity 2, so they touch only geoms with contype 2.
/// `timestep_s` sets the floor of the membrane lattice's shear damping (its stiffest
/// shear mode must stay stable under explicit integration of the tendon springs).
/// Every pin carries a site at its inner end (the marker the internal camera sees) and,
/// where `outer_site[i]`, one at its outer contact point (external markers); the overload
/// without `outer_site` gives every pin both. Elements are named by `names`.
SkinPart BuildSkin(const SkinConfig& skin, const ContactConfig& contact, const PinLattice& lattice,
                   const std::vector<bool>& collidable, double timestep_s, const std::vector<bool>& outer_site,
                   const SkinNames& names = {});
SkinPart BuildSkin(const SkinConfig& skin, const ContactConfig& contact, const PinLattice& lattice,
                   const std::vector<bool>& collidable, double timestep_s);

}  // namespace tactip
