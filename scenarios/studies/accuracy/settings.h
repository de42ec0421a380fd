#pragma once
// The numerical settings an accuracy study sweeps, one override list each: the reference
// (the finest), the default, and one change at a time of the timestep, solver iterations
// and tolerance, noslip pass, cone and impratio, and contact softness.

#include <string>
#include <vector>

namespace tactip {

/// One numerical setting of an accuracy study.
struct AccuracySetting {
  std::string label;                   ///< short name, e.g. "dt=1ms"
  std::vector<std::string> overrides;  ///< "key=value", applied after the scene's config
  bool is_reference = false;           ///< the finest setting everything is compared with
  bool is_default = false;             ///< the built-in defaults
};

/// Settings for the rail and incipient scenes (the reference first): the timesteps are a
/// quarter (the reference), half, three quarters and 1.25 times the scene's default step, so a
/// scene whose skin defaults to a finer step is swept around its own default.
std::vector<AccuracySetting> RailAccuracySettings(double default_step_s, double timeconst_s);

/// Settings for the dome checks (timestep, solver, noslip, contact softness; reference first).
std::vector<AccuracySetting> DomeAccuracySettings();

/// The setting named `label`; throws InputError listing the labels.
const AccuracySetting& FindSetting(const std::vector<AccuracySetting>& settings, const std::string& label);

}  // namespace tactip
