#pragma once
// The `--skin NAME` presets: the skin keys and the step each of smooth, fingerprint-v1 and
// fingerprint-v2 sets in a scene's config.

#include <optional>
#include <string>
#include <vector>

#include "models/skin_timesteps.h"

namespace tactip {

/// The skin keys of the `--skin NAME` presets: "skin.key=value" overrides for smooth,
/// fingerprint-v1 and fingerprint-v2 (throws InputError for another name). The fingerprint
/// presets carry the membrane lattice's resolved materials (a gel of 6.67 kPa in shear, a
/// 0.4 MPa skin, the rim clamped); the smooth skin keeps the defaults.
std::vector<std::string> SkinPreset(const std::string& name);

/// The step `--skin NAME` sets: none for the smooth skin (the scene's default), the validated
/// step kShearDofValidatedStepS for fingerprint-v1, kFingerprintV2StepS for fingerprint-v2.
std::optional<double> SkinPresetTimestep(const std::string& name);

/// What `--skin NAME` sets in a scene's config: SkinPreset and, for a fingerprint skin (per-pin
/// shear DOFs), its step sim.timestep_s = SkinPresetTimestep(name).
std::vector<std::string> SkinPresetOverrides(const std::string& name);

}  // namespace tactip
