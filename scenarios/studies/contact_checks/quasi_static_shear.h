#pragma once
// The exact quasi-static Coulomb solution of a shear-coupled pin lattice under a flat plate:
// the dome check's reference (`tactip validate contact`).

#include <cstdint>
#include <vector>

#include "models/membrane_elements.h"
#include "models/skin.h"

namespace tactip {

/// The exact quasi-static Coulomb solution of a lattice sheared by a rigid flat plate
/// (SolveQuasiStaticShear below).
struct QuasiStaticShear {
  std::vector<double> release_q;   ///< per pin: Q / (mu P) at which it slips (NaN: not in contact)
  std::vector<double> release_delta_m;  ///< per pin: plate displacement at which it slips
  double gross_delta_m = 0.0;      ///< plate displacement at which the last pin slips
  /// A uniform grid of plate displacement up to gross slip (the dome check's ramp samples at
  /// constant speed, so the two sample alike) and Q / (mu P) on it.
  std::vector<double> grid_delta_m, grid_q;

  /// Whether pin i still sticks at plate displacement delta (a pin counts as slipped from
  /// its release on).
  bool StuckAt(size_t i, double delta) const { return delta < release_delta_m[i]; }
};

/// The in-plane shear stiffness of a lattice's contact points for the exact solution: each
/// pin's own spring (on both components) and a 2x2 block per lattice edge. Components: y, the
/// plate's shear axis (the sensor's y), and z, across it.
struct LatticeShearStiffness {
  struct Link {
    int a = 0, b = 0;                        ///< the two pins
    double k_yy = 0.0, k_yz = 0.0, k_zz = 0.0;  ///< the link's block, N/m
  };
  std::vector<double> k_tip_N_m;  ///< per pin
  std::vector<Link> links;
  std::vector<MembraneMode> modes;  ///< the orthotropic membrane's triangles, k a a^T each

  /// Links that pull on both components alike (skin.membrane_links = isotropic): k_couple I.
  static LatticeShearStiffness Isotropic(const PinLattice& lattice, const std::vector<double>& k_tip_N_m,
                                         double k_couple_N_m);
  /// The skin's own lattice: SkinMechanics::TipStiffness per pin, and its links isotropic or,
  /// with mech.central_links, each along itself (k e e^T, SkinMechanics::CentralLinkBetween);
  /// with mech.orthotropic_links, no links but the membrane's modes (OrthotropicMembraneModes).
  static LatticeShearStiffness Of(const PinLattice& lattice, const SkinMechanics& mech);
};

/// Exact quasi-static Coulomb solution of a membrane-coupled lattice sheared by a rigid
/// flat plate along y. Two shear DOFs per pin; isotropic links leave the loaded component
/// decoupled (K = k_tip I + k_couple L, L the graph Laplacian), central links couple it to
/// the transverse one (Poisson's effect of a central-spring network). A sticking pin moves
/// with the plate (u_i = (delta, 0)); it slips when its friction force reaches mu N_i in
/// magnitude, and from then on carries mu N_i along its slip: from the direction its force had
/// at release (on isotropic links always +y), the direction turns so that the pin slides along
/// it (its slip rate (1, 0) - du_i/ddelta parallel to it) with the lattice in equilibrium —
/// on central links, whose slipped pins let go with a sideways share, towards +y as the plate
/// drags them, integrated over 1000 steps of the travel to gross slip; a pin out of
/// contact carries nothing. The normal loads stay those of the press (a flat plate's contact
/// normal does not turn with shear). The stuck set only loses pins as delta grows, and
/// between two releases (and turns) every force is affine in delta, so the releases are found
/// exactly, one event at a time. `presliding_m` > 0 ties each sticking pin to the plate by its
/// pre-sliding spring mu N_i / presliding_m on both components (the friction pass's contact
/// law); 0 is rigid stick. Throws SimulationError when no pin is in contact,
/// std::invalid_argument when the loads do not match the lattice.
QuasiStaticShear SolveQuasiStaticShear(const LatticeShearStiffness& stiffness, const std::vector<double>& normal_N,
                                       const std::vector<std::uint8_t>& in_contact, double mu, int grid_points,
                                       double presliding_m = 0.0);

/// The same on isotropic links: shear stiffness k_tip per pin, k_couple per lattice edge.
QuasiStaticShear SolveQuasiStaticShear(const PinLattice& lattice, double k_tip_N_m, double k_couple_N_m,
                                       const std::vector<double>& normal_N, const std::vector<std::uint8_t>& in_contact,
                                       double mu, int grid_points, double presliding_m = 0.0);
/// The same with each pin's own shear stiffness (SkinMechanics::TipStiffness: the outer ring
/// of a clamped rim carries its share of the annulus).
QuasiStaticShear SolveQuasiStaticShear(const PinLattice& lattice, const std::vector<double>& k_tip_N_m,
                                       double k_couple_N_m, const std::vector<double>& normal_N,
                                       const std::vector<std::uint8_t>& in_contact, double mu, int grid_points,
                                       double presliding_m = 0.0);

}  // namespace tactip
