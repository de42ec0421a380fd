#include "models/skin_presets.h"

#include <fmt/format.h>

#include "sim/config.h"

namespace tactip {

namespace {
// The membrane lattice resolves the skin (its stretch, its ridges, its rim), so its gel is the
// gel's own: a very soft silicone, 6.67 kPa in shear, under a 0.4 MPa skin clamped at the dome's
// base (docs/fingerprint-skins.md 'The skin's materials'). The smooth skin's rigid shell keeps the lumped defaults.
const std::vector<std::string> kResolvedMaterials = {"skin.gel_shear_modulus_kpa=6.67", "skin.skin_modulus_mpa=0.4",
                                                     "skin.rim=clamped"};

std::vector<std::string> WithResolvedMaterials(std::vector<std::string> keys) {
  keys.insert(keys.end(), kResolvedMaterials.begin(), kResolvedMaterials.end());
  return keys;
}
}  // namespace

std::vector<std::string> SkinPreset(const std::string& name) {
  if (name == "smooth") {
    // The lumped materials, also where a scenario's defaults carry a fingerprint preset's.
    return {"skin.pattern=smooth", "skin.coupling=shell", "skin.gel_shear_modulus_kpa=10", "skin.skin_modulus_mpa=1",
            "skin.rim=free"};
  }
  if (name == "fingerprint-v1") {
    return WithResolvedMaterials({"skin.pattern=fingerprint-v1", "skin.coupling=membrane", "skin.ridge_spacing_mm=4",
                                  "skin.ridge_height_mm=2", "skin.ridge_shape=square", "skin.thickness_mm=0.5",
                                  "skin.pin_length_mm=2", "skin.pins_per_ring=6", "skin.pattern_radius_mm=20"});
  }
  if (name == "fingerprint-v2") {
    return WithResolvedMaterials({"skin.pattern=fingerprint-v2", "skin.coupling=membrane", "skin.ridge_spacing_mm=3",
                                  "skin.ridge_height_mm=2", "skin.ridge_shape=sine", "skin.thickness_mm=1",
                                  "skin.pin_length_mm=1", "skin.pins_per_ring=6", "skin.pattern_radius_mm=18"});
  }
  throw InputError("--skin '" + config_detail::Escaped(name) + "': unknown skin (known: smooth, fingerprint-v1, fingerprint-v2)");
}

std::optional<double> SkinPresetTimestep(const std::string& name) {
  if (name == "fingerprint-v1") return kShearDofValidatedStepS;
  if (name == "fingerprint-v2") return kFingerprintV2StepS;
  return std::nullopt;
}

std::vector<std::string> SkinPresetOverrides(const std::string& name) {
  std::vector<std::string> keys = SkinPreset(name);
  if (const auto step = SkinPresetTimestep(name)) keys.push_back(fmt::format("sim.timestep_s={}", *step));
  return keys;
}

}  // namespace tactip
