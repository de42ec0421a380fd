#pragma once
// The exact quasi-static Coulomb solution of a shear-coupled pin lattice under a flat plate:
// the dome check's reference (`tactip validate contact`).

#include <cstdint>
#include <vector>

#include "models/skin.h"

namespace tactip {

/// Exact quasi-static Coulomb solution of a membrane-coupled lattice sheared by a rigid
/// flat plate along one in-plane axis. The shear DOFs of the lattice are world-aligned, so
/// the loaded component decouples: stiffness K = k_tip I + k_couple L (L the graph
/// Laplacian of the lattice edges). A sticking pin moves with the plate (u_i = delta), a
/// slipping pin carries mu N_i, a pin out of contact carries nothing; the normal loads stay
/// those of the press (a flat plate's contact normal does not turn with shear). The stuck set
/// only loses pins as delta grows, and between two releases every force is affine in delta,
/// so the releases are found exactly, one event at a time.
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

/// Exact quasi-static solution of a membrane-coupled lattice (shear stiffness k_tip per
/// pin, k_couple per lattice edge) under a flat plate moving tangentially: each pin's
/// release load, event by event. `presliding_m` > 0 ties each sticking pin to the plate by
/// its pre-sliding spring mu N_i / presliding_m (the friction pass's contact law); 0 is
/// rigid stick. Throws SimulationError when no pin is in contact.
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
