#pragma once
// The ridges of a fingerprint skin: the share of the ridges each pin carries (its gel cell on
// the ring, its ridge's rocking against the gel and the skin hinges, the lever its marker sees),
// and the corrugated sheet the concentric ridges make of the skin. The gel's share of a ridge's
// rocking is models/ridge_rocking.h.

#include "models/skin_config.h"

namespace tactip {

/// One pin's ridge on a fingerprint pattern (SI units): its cell of the ring and the ridge's
/// rocking compliance at the contact point.
struct RidgeCell {
  double step_m = 0.0;              ///< radial step between ridge rings: the cell's depth and the neighbour distance
  double arc_m = 0.0;               ///< the cell's length along the ring, 2 pi k s / (ppr k) = 2 pi s / pins_per_ring
  double k_rock_N_m = 0.0;          ///< ridge rocking stiffness at the contact point, k_theta / lever^2
  double marker_rock_factor = 0.0;  ///< inner marker = contact point - this * ridge deflection

  /// The ridge cell of a fingerprint `skin` whose skin plate has the bending rigidity
  /// `plate_rigidity_N_m` (D = E t^3 / (12 (1 - nu^2)), N m): the gel under the ridge's base
  /// (RockingGelStiffness) against its tilt, plus the skin hinges in the valleys on both sides.
  static RidgeCell Of(const SkinConfig& skin, double plate_rigidity_N_m);
};

/// The concentric ridges make a fingerprint skin a corrugated sheet (docs/fingerprint-skins.md
/// 'Orthotropic membrane'; flat for the smooth skin).
struct Corrugation {
  /// Radial compliance over the flat sheet's: stretched across its waves the sheet bends as
  /// well as stretches, 1 + 6 (1 - nu^2) (a / t)^2, a the waves' amplitude (half the ridge height).
  double radial_factor = 1.0;
  /// Developed over projected length of one ridge period: the hoop direction has that much more
  /// rubber per unit width, in-plane shear runs that much longer a path.
  double length_ratio = 1.0;
  /// The corrugation of `skin`'s ridges (the flat sheet, both factors 1, for the smooth skin).
  static Corrugation Of(const SkinConfig& skin);
};

}  // namespace tactip
