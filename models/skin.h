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
#include "models/contact_config.h"
#include "models/fingerprint_ridges.h"
#include "models/pin_lattice.h"
#include "models/skin_config.h"
#include "models/skin_presets.h"
#include "models/skin_timesteps.h"
#include "sim/config.h"

namespace tactip {

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
