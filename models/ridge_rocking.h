#pragma once
// A fingerprint ridge rocking on its base: the gel's share of its rotational stiffness
// (skin.ridge_rocking). The skin hinges in the valleys beside it are SkinMechanics'.

#include <string>

namespace tactip {

/// The gel's resistance to a ridge's base (width w, length b, m) tilting on it, N m/rad, for
/// a gel of Young's modulus E_gel (Pa, Poisson ratio 1/2) and depth h_gel (m):
///   "winkler":    the gel columns of depth h_gel under the base, (E_gel / h_gel) b w^3 / 12;
///   "half-space": a rigid strip of half-width c = w / 2 tilted by theta on an elastic
///                 half-space (plane strain) carries p(x) = E* theta x / (2 sqrt(c^2 - x^2)),
///                 whose moment is pi E* c^2 theta / 4 per unit length: pi E* b w^2 / 16,
///                 E* = E_gel / (1 - 1/4). The base is bonded, so its lifted half pulls.
/// The two differ by pi h_gel / w. Throws std::invalid_argument for another model name.
double RockingGelStiffness(const std::string& model, double E_gel, double h_gel, double b, double w);

}  // namespace tactip
