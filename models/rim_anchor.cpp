#include "models/rim_anchor.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "models/skin.h"

namespace tactip {

double ClampedAnnulusTranslationStiffness(double mu_t_N_m, double nu, double inner_m, double outer_m) {
  if (!(inner_m > 0.0 && outer_m > inner_m && mu_t_N_m > 0.0 && nu > -1.0 && nu <= 0.5)) {
    throw std::invalid_argument("ClampedAnnulusTranslationStiffness: needs 0 < inner < outer, mu_t > 0, -1 < nu <= 0.5");
  }
  const double kappa = (3.0 - nu) / (1.0 + nu);
  const double a2 = inner_m * inner_m, b2 = outer_m * outer_m;
  const double denominator = kappa * std::log(outer_m / inner_m) - (b2 - a2) / (kappa * (a2 + b2));
  return 2.0 * std::numbers::pi * mu_t_N_m * (1.0 + kappa) / denominator;
}

RimAnchor RimAnchor::Of(const SkinConfig& skin, const PinLattice& lattice) {
  RimAnchor out;
  if (skin.rim != "clamped" || skin.coupling == "none" || lattice.pins.empty()) return out;
  const double R = skin.radius_mm * 1e-3;
  int outer = 0;
  for (const auto& pin : lattice.pins) outer = std::max(outer, pin.ring);
  double arc_sum = 0.0;
  int count = 0;
  for (const auto& pin : lattice.pins) {
    if (pin.ring != outer) continue;
    arc_sum += pin.polar_rad * R;
    ++count;
  }
  out.pattern_edge_m = arc_sum / count + 0.5 * skin.RingStepMm() * 1e-3;
  out.rim_m = skin.BaseArcMm() * 1e-3;
  if (out.pattern_edge_m >= out.rim_m) return out;  // the pattern reaches the rim: ValidateRules refuses it
  // The network's 2-D Young's modulus is E t; its shear modulus E t / (2 (1 + nu)).
  const double mu_t = skin.skin_modulus_mpa * 1e6 * skin.thickness_mm * 1e-3 / (2.0 * (1.0 + kMembranePoisson));
  out.k_N_m = ClampedAnnulusTranslationStiffness(mu_t, kMembranePoisson, out.pattern_edge_m, out.rim_m);
  out.outer_ring = outer;
  out.outer_ring_pins = count;
  return out;
}

}  // namespace tactip
