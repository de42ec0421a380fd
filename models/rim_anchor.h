#pragma once
// The skin beyond the pin pattern: an annulus of skin rubber from the pattern's edge to the
// rim where the skin is clamped to the sensor's base. It pulls a sheared pattern back.

#include <vector>

namespace tactip {

struct SkinConfig;
struct PinLattice;

/// In-plane membrane of the skin rubber as the pin lattice models it: a triangular spring
/// network, whose 2-D Poisson ratio is 1/3 (docs/fingerprint-skins.md 'The skin's rim').
inline constexpr double kMembranePoisson = 1.0 / 3.0;

/// Force per unit translation (N/m) of a rigid disc of radius inner_m bonded inside a flat
/// annular membrane clamped at outer_m (plane stress; shear modulus times thickness mu_t in
/// N/m, Poisson ratio nu). Kolosov-Muskhelishvili solution with kappa = (3 - nu) / (1 + nu):
///   K = 2 pi mu_t (1 + kappa) / (kappa ln(b/a) - (b^2 - a^2) / (kappa (a^2 + b^2))).
/// Throws std::invalid_argument unless 0 < inner_m < outer_m, mu_t > 0 and -1 < nu <= 0.5.
double ClampedAnnulusTranslationStiffness(double mu_t_N_m, double nu, double inner_m, double outer_m);

/// How the skin beyond the pattern holds the pattern in-plane (skin.rim).
struct RimAnchor {
  double pattern_edge_m = 0.0;  ///< arc radius of the pattern's edge: outermost ring's mean + half a step
  double rim_m = 0.0;           ///< arc radius of the clamped rim: the dome's base, pi R / 2
  double k_N_m = 0.0;           ///< stiffness against a translation of the whole pattern, per in-plane axis
  int outer_ring = -1;          ///< the ring whose pins the annulus holds (-1: none, skin.rim = free)
  int outer_ring_pins = 0;      ///< pins on that ring

  /// The annulus of `skin` around `lattice` (all zero with skin.rim = free or coupling none).
  static RimAnchor Of(const SkinConfig& skin, const PinLattice& lattice);
  /// Each outer-ring pin's share of k_N_m (0 without an anchor).
  double PerPinN_m() const { return outer_ring_pins > 0 ? k_N_m / outer_ring_pins : 0.0; }
};

}  // namespace tactip
