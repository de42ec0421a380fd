#pragma once
// The steps at which the skins are validated, and the one the fingerprint-v2 preset sets
// (models/stability.h applies them; models/skin_presets.h sets them with `--skin NAME`).

namespace tactip {

/// Largest step at which a skin with per-pin shear DOFs is validated at mu = 1, s (see
/// ShearDofValidatedTimestep in models/stability.h).
inline constexpr double kShearDofValidatedStepS = 0.001;

/// A shell skin whose in-plane mode is damped below this ratio (SkinConfig::ShellDampingRatio)
/// rings after its release, and is validated with a sliding step up to kLightShellValidatedStepS only.
inline constexpr double kLightShellDampingRatio = 0.5;

/// Largest sliding step (from the gross-slip onset on) at which a lightly damped shell skin is
/// validated, s; its held phase takes the default 2 ms (gel 0.08, flat at 0.1 and 1 mm/s and the
/// four held-phase scenes: healthy, onsets within 3 ms of 1 ms throughout). At 2 ms the released
/// shell's ringing makes the sliding contacts chatter during gross slip (the total normal force
/// of the flat press at 1 mm/s falls to 0.04 of its value at the onset with 6 of 19 pins in
/// contact under the gel's 0.08, to 0.50 with 12 of 19 under a fixed damper at 0.1, to 0.69 with
/// 13 at 0.3; at 0.5 and above it stays at 0.81 or more with all 19). At 1 ms it stays at 0.92
/// (gel 0.08) and 0.94 (fixed 0.1) with all 19 (docs/model.md, 'The pin-lattice skin').
inline constexpr double kLightShellValidatedStepS = 0.001;

/// The step the fingerprint-v2 preset sets, s. At the 1 ms validated step v2's edge contacts
/// lift off and touch the object again as the ridges let go in turn (9 of 10 incipient runs
/// flagged by run health, one pin at 0.02-55 mN); at 0.5 ms 1 of 10 (0.02 mN), and the gross
/// onsets of those ten runs lie 0.08 s (mean) from the 0.25 ms ones against 0.19 s at 1 ms
/// (docs/numerics.md, 'Numerical stability').
inline constexpr double kFingerprintV2StepS = 0.0005;

}  // namespace tactip
