#include "models/fingerprint_ridges.h"

#include <cmath>
#include <numbers>

#include "models/ridge_rocking.h"

namespace tactip {

namespace {

// Developed over projected length of one period of the ridge profile.
double RidgeLengthRatio(const SkinConfig& skin) {
  const double h = skin.ridge_height_mm, s = skin.ridge_spacing_mm;
  if (skin.ridge_shape == "square") return 1.0 + 2.0 * h / s;  // up, across, down
  // Sine of amplitude h / 2: the mean of sqrt(1 + (k cos x)^2) over a period, k = pi h / s.
  const double k = std::numbers::pi * h / s;
  constexpr int kSamples = 2048;
  double sum = 0.0;
  for (int i = 0; i < kSamples; ++i) {
    const double c = std::cos(2.0 * std::numbers::pi * (i + 0.5) / kSamples);
    sum += std::sqrt(1.0 + k * k * c * c);
  }
  return sum / kSamples;
}
}  // namespace

RidgeCell RidgeCell::Of(const SkinConfig& skin, double plate_rigidity_N_m) {
  const double E_gel = skin.gel_modulus_kpa * 1e3;
  const double h_gel = skin.gel_depth_mm * 1e-3;
  const double t = skin.thickness_mm * 1e-3;
  const double D = plate_rigidity_N_m;
  RidgeCell cell;
  // A pin's cell: one ring step by the arc per pin, 2 pi k s / (ppr k).
  const double a = skin.ridge_spacing_mm * 1e-3;
  const double b = 2.0 * std::numbers::pi * a / skin.pins_per_ring;
  cell.step_m = a;
  cell.arc_m = b;
  // Ridge rocking: a ridge of base width w = s / 2 (with its pin) tilts on the gel
  // (RockingGelStiffness) against the skin hinges in the valleys on both sides (plate
  // bending, 2 D b / valley). At the contact point, k_rock = k_theta / lever^2.
  const double w = 0.5 * a, valley = a - w;
  const double k_theta = RockingGelStiffness(skin.ridge_rocking, E_gel, h_gel, b, w) + 2.0 * D * b / valley;
  const double h = skin.ridge_height_mm * 1e-3;
  const double lever = skin.ridge_shape == "square" ? h : 0.5 * h;
  cell.k_rock_N_m = k_theta / (lever * lever);
  // The camera sees v1's pin inner end a skin thickness below the pivot at the ridge
  // root, so it moves against the contact point; v2's pins run through the skin at
  // the peak and move with the skin under it.
  cell.marker_rock_factor = skin.pattern == "fingerprint-v1" ? 1.0 + t / lever : 1.0;
  return cell;
}

Corrugation Corrugation::Of(const SkinConfig& skin) {
  if (!skin.Fingerprint()) return {};
  const double a_over_t = 0.5 * skin.ridge_height_mm / skin.thickness_mm;
  const double nu = kRubberPoisson;
  return {1.0 + 6.0 * (1.0 - nu * nu) * a_over_t * a_over_t, RidgeLengthRatio(skin)};
}

}  // namespace tactip
