#include "models/skin_config.h"

#include <algorithm>
#include <numbers>

#include <fmt/format.h>

namespace tactip {

double SkinConfig::OuterRadiusMm() const { return radius_mm + (Fingerprint() ? ridge_height_mm : 0.0); }

double SkinConfig::GelShearModulusPa() const {
  return (gel_shear_modulus_kpa > 0.0 ? gel_shear_modulus_kpa : gel_modulus_kpa / 3.0) * 1e3;
}

double SkinConfig::ContactRadiusMm() const {
  return Fingerprint() ? std::min(contact_radius_mm, 0.5 * ridge_spacing_mm) : contact_radius_mm;
}

void SkinConfig::ValidateRules() const {
  const double reach_mm = Fingerprint() ? pattern_radius_mm : rings * pitch_mm;
  const double alpha_max = reach_mm / radius_mm;
  if (alpha_max >= 0.5 * std::numbers::pi) {
    const char* key = Fingerprint() ? "skin.pattern_radius_mm" : "skin.rings";
    FailRule(key, Fingerprint() ? pattern_radius_mm : rings,
             fmt::format("lattice reaches {:.2f} rad from the apex; it must stay within pi/2 * radius_mm "
                         "({:.1f} mm of arc)",
                         alpha_max, BaseArcMm()));
  }
  if (Fingerprint() && pattern_radius_mm < ridge_spacing_mm) {
    FailRule("skin.pattern_radius_mm", pattern_radius_mm, "must be >= skin.ridge_spacing_mm (at least one ring)");
  }
  if (thickness_mm + pin_length_mm >= radius_mm) {
    FailRule("skin.pin_length_mm", pin_length_mm, "thickness_mm + pin_length_mm must be < radius_mm");
  }
  if (pattern == "fingerprint-v2" && pin_length_mm > ridge_height_mm + thickness_mm) {
    FailRule("skin.pin_length_mm", pin_length_mm,
             "fingerprint-v2 pins run from the wave peak through the skin: must be <= ridge_height_mm + thickness_mm");
  }
  if (membrane_links == "orthotropic" && coupling == "membrane" && !Fingerprint()) {
    FailRule("skin.membrane_links", membrane_links,
             "the orthotropic membrane is the concentric ridges' corrugated sheet: needs a fingerprint pattern");
  }
  if (contact_radius_mm >= radius_mm) {
    FailRule("skin.contact_radius_mm", contact_radius_mm, "must be < radius_mm");
  }
  if (DomeSprings() && pattern == "fingerprint-v1") {
    // Measured (docs/fingerprint-skins.md 'Dome springs'): 10 of 10 v1 incipient runs flagged by run health.
    FailRule("skin.normal_spring", normal_spring,
             "fingerprint-v1's edge pins flicker in and out of contact while held on dome springs (their runs "
             "are flagged by run health); use axial");
  }
  // The configured reach bounds the outermost ring, so this edge is never inside RimAnchor's.
  const double edge_mm = reach_mm + 0.5 * RingStepMm();
  if (rim == "clamped" && edge_mm >= BaseArcMm()) {
    FailRule("skin.rim", rim,
             fmt::format("the pattern's edge ({:.1f} mm of arc) must lie inside the clamped rim at the dome's base "
                         "({:.1f} mm)",
                         edge_mm, BaseArcMm()));
  }
}

}  // namespace tactip
