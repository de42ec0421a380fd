#pragma once
// The skin's configuration (the `skin.` section): its keys with their units, documentation and
// bounds, the quantities read straight off them, and the cross-field rules.

#include <numbers>
#include <string>

#include "sim/config.h"

namespace tactip {

/// The range of skin.skin_modulus_mpa: from a soft silicone gel's few kPa to a stiff rubber's.
/// Poisson's ratio of the skin's and the gel's rubber: nearly incompressible.
inline constexpr double kRubberPoisson = 0.5;

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

  /// Lists every key of the section in order (sim/config.h), one group of keys per helper.
  template <class V>
  void Visit(V& v) {
    VisitGeometry(v);
    VisitMaterials(v);
    VisitDamping(v);
    VisitCoupling(v);
    VisitPattern(v);
    VisitMarkers(v);
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

 private:
  /// The dome and the hexagonal pin lattice on it: radius, pitch, rings, skin thickness, pins.
  template <class V>
  void VisitGeometry(V& v) {
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
  }
  /// The gel's and the skin rubber's moduli, and the gel's depth.
  template <class V>
  void VisitMaterials(V& v) {
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
      "and misses at 13 (docs/model.md 'The smooth skin's shear'); the fingerprint presets, whose membrane "
      "lattice resolves the skin, set 6.67 (docs/fingerprint-skins.md 'The skin's materials'). 0: "
      "gel_modulus_kpa / 3, the column's own modulus taken as an incompressible solid (the smooth shell before "
      "the calibration, 1650 N/m).",
      Bounds::Closed(0.0, 10000.0));
    v("skin_modulus_mpa", skin_modulus_mpa, "MPa",
      "Young's modulus of the skin rubber (Shore A 26-28 -> ~1 MPa by Gent's relation; the fingerprint presets "
      "set a fitted 0.4 MPa, docs/fingerprint-skins.md 'The skin's materials').",
      Bounds::Closed(kSkinModulusMinMpa, kSkinModulusMaxMpa));
  }
  /// The damping of the pins' normal and shear modes and of the shell.
  template <class V>
  void VisitDamping(V& v) {
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
      "(sim.sliding_timestep_s, from the gross-slip onset on) up to 0.001 s (docs/model.md 'The pin-lattice "
      "skin').",
      Choices{"viscous", "gel"});
    v("gel_loss_tangent", gel_loss_tangent, "",
      "Loss tangent tan(delta) = G''/G' of the gel's shear modulus (shell_damping = gel): the shell's in-plane "
      "modes are damped at a ratio tan(delta) / 2. Soft silicone gels have 0.05-0.3 at 1-100 Hz; 0.16 (ratio "
      "0.08) lies mid-range (docs/model.md 'The pin-lattice skin').",
      Bounds::Closed(0.01, 2.0));
  }
  /// The contact patch, and how the pins are coupled through the skin and held at its rim.
  template <class V>
  void VisitCoupling(V& v) {
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
      "shear springs (shell) or shared by the outermost ring's pins (membrane). See docs/fingerprint-skins.md "
      "'The skin's rim'.",
      Choices{"free", "clamped"});
    v("membrane_links", membrane_links, "",
      "How a membrane lattice's link (coupling membrane; the shell and none ignore this) pulls on its two pins' "
      "contact points. isotropic: on both in-plane components, k_couple = link in series with two ridges. "
      "central: along the link only, as the triangular spring network that k_link = (sqrt 3 / 2) E t is derived "
      "from; a ridge rocks only across itself, so the ridges enter by the link's radial share c: k = 1 / (1 / "
      "k_link + 2 c^2 / k_rock), which is k_couple for a radial link, k_link along a ring. At a step of 0.25 ms "
      "or finer it puts v2's first slip on the east/west sides in most runs at 0.1-0.5 mm/s "
      "(docs/fingerprint-skins.md 'Membrane links'); opt-in. 'validate contact' judges it against its exact "
      "quasi-static solution on central links (docs/validation.md 'Contact validation'). orthotropic: the skin "
      "between the pins as linear triangles of a corrugated sheet - the concentric ridges make it radially soft "
      "(stretched across its waves it bends, compliance 1 + 6 (1 - nu^2) (a / t)^2, a half the ridge height) "
      "and hoop stiff (the developed length), shear carried along the developed path - scaled by k_couple / "
      "k_link for the ridges' rocking; fingerprint patterns only; opt-in; 'validate contact' judges it against "
      "its exact solution too (docs/fingerprint-skins.md 'Orthotropic membrane').",
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
      "the lattice's widest pin, and the shear joints take that mode's damping floor too "
      "(docs/fingerprint-skins.md 'Dome springs'). Opt-in; refused on fingerprint-v1 (its edge pins flicker in "
      "and out of contact while held) and by 'validate contact' and 'accuracy domes' (their exact solution has "
      "axial springs).",
      Choices{"axial", "dome"});
  }
  /// The outer pattern: smooth, or a fingerprint's ridges and the pin rings under them.
  template <class V>
  void VisitPattern(V& v) {
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
      "times stiffer (k_rock 9.3 -> 115 N/m), v2's twice (191 -> 371 N/m). Opt-in; docs/fingerprint-skins.md "
      "'Ridge rocking' gives the figures it moves.",
      Choices{"winkler", "half-space"});
    v("pins_per_ring", pins_per_ring, "", "Fingerprint: ring k (k >= 1) carries pins_per_ring * k pins.",
      Bounds::Closed(1, 24));
    v("pattern_radius_mm", pattern_radius_mm, "mm",
      "Fingerprint: arc radius of the outermost ring; rings sit at k * ridge_spacing_mm <= this.",
      Bounds::Closed(1.0, 60.0));
  }
  /// What moves the markers: the pins alone, or the gel's lateral flow as well.
  template <class V>
  void VisitMarkers(V& v) {
    v("marker_model", marker_model, "",
      "What moves the markers the cameras see. gel: each pin's body (MuJoCo) plus the gel's lateral flow - an "
      "indented pin squeezes the incompressible gel sideways and the flow carries every marker outwards, so a "
      "press moves all markers, the outer ring too, as on a real TacTip. pins: the pin bodies alone (the contact "
      "dynamics are the same; only the markers differ). See docs/model.md 'Marker kinematics: the gel field'.",
      Choices{"gel", "pins"});
    v("gel_flow_depth_mm", gel_flow_depth_mm, "mm",
      "Gel field: depth of the gel layer under the skin that flows sideways with it (a squeezed volume V moves "
      "the skin by V / (2 pi h s) at distance s). 2.5 mm, with gel_squeeze_mm 0.5, puts a flat press's marker "
      "field within a factor 1.5 of a real 127-pin TacTip's at 2-4 mm (docs/validation.md 'Marker check').",
      Bounds::Closed(0.1, 50.0));
    v("gel_squeeze_mm", gel_squeeze_mm, "mm",
      "Gel field: a pin indented by w squeezes a gel volume h tanh(w / h) per unit cell area sideways, h this "
      "value; deeper indentation pushes the gel column towards the core instead. 0.5 mm gives the real TacTip's "
      "steep rise by 1 mm and slow growth after (docs/validation.md 'Marker check').",
      Bounds::Closed(0.01, 5.0));
  }
};

}  // namespace tactip
