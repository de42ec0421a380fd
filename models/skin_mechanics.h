#pragma once
// The skin's mechanics: the spring constants, masses and damping the pin lattice's MJCF
// carries, derived from the config's materials (SkinMechanics), with the bounds on its
// stiffest modes that set the damping floors at a timestep.

#include <cstddef>

#include "models/fingerprint_ridges.h"
#include "models/pin_lattice.h"
#include "models/skin_config.h"

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
  double pin_mass_kg = 0.0;         ///< moving mass per pin
  double shell_mass_kg = 0.0;       ///< skin membrane mass
  double shell_moving_mass_kg = 0.0;  ///< what the shell's in-plane joints carry: membrane plus every pin
  double pin_damping_Ns_m = 0.0;    ///< normal-mode damping per pin
  double shell_damping_Ns_m = 0.0;  ///< damping of the skin's in-plane translation
  double membrane_N_m = 0.0;        ///< in-plane membrane stiffness E t (reported; docs/model.md 'The pin-lattice skin')
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
  double dome_shear_row_N_m = 0.0;  ///< the widest shear-joint row above (0: axial springs)
  // The clamped rim (skin.rim = clamped; set by From(skin, lattice), else zero):
  double k_rim_N_m = 0.0;           ///< the skin annulus against a translation of the whole pattern (RimAnchor)
  double k_rim_pin_N_m = 0.0;       ///< membrane lattice: an outer-ring pin's share, in series with its ridge
  int rim_ring = -1;                ///< the ring the annulus holds (-1: none)

  /// From the config alone, for a lattice of n_pins pins; what needs the lattice keeps its
  /// default (max_degree 6, no clamped rim, no central or orthotropic row sums, no dome bounds).
  static SkinMechanics From(const SkinConfig& skin, size_t n_pins);
  /// With the lattice: the neighbour count enters the stiffest shear mode.
  static SkinMechanics From(const SkinConfig& skin, const PinLattice& lattice);
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
  /// A central link's stiffness along itself (defined with the other link code in
  /// models/membrane_links.cpp) (skin.membrane_links = central), N/m: the
  /// membrane spring in series with the two ridges' rocking, which takes the link's radial
  /// share `radial_share` (cosine between the link and the radial direction, 0..1).
  double CentralLinkStiffness(double radial_share) const;
  /// A central link between two pins: its unit direction (y, z) in the sensor's plane and its
  /// stiffness along it.
  struct CentralLink {
    double ey = 0.0;     ///< unit direction, y component (from pin a to pin b)
    double ez = 0.0;     ///< unit direction, z component
    double k_N_m = 0.0;  ///< stiffness along the link (CentralLinkStiffness)
  };
  /// The central link between pins a and b (models/membrane_links.cpp).
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

}  // namespace tactip
