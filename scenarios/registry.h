#pragma once
// The one place where scenarios are named. The command line lists and runs them
// through this registry.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "scenarios/rail.h"
#include "sim/config.h"

namespace tactip {

/// How a scenario is configured from the command line: a YAML file and key=value
/// overrides applied in order on top of the built-in defaults.
struct ConfigSource {
  std::string yaml_path;               ///< empty: defaults only
  std::vector<std::string> overrides;  ///< "key=value", applied after the file
  /// Choose sim.timestep_s by ChooseTimestep after the file and the overrides (the step they
  /// configure is the upper cap), before the config is validated.
  bool auto_timestep = false;
};

/// A scenario's config as resolved from a ConfigSource.
struct ResolvedConfig {
  RailScenarioConfig config;              ///< validated
  std::optional<TimestepChoice> timestep; ///< the step chosen (ConfigSource::auto_timestep)
};

/// A registered scenario.
struct ScenarioEntry {
  std::string name;         ///< command-line name
  std::string description;  ///< one line for `tactip scenarios`
  /// The resolved, validated config (throws InputError).
  std::function<RailScenarioConfig(const ConfigSource&)> load;
  /// The same with the timestep chosen, if it was (throws InputError).
  std::function<ResolvedConfig(const ConfigSource&)> resolve;
  /// Documentation of every config field (with defaults, or with the source applied).
  std::function<std::vector<FieldDoc>(const ConfigSource&)> describe;
  /// The MJCF of the scene the scenario builds for this config.
  std::function<std::string(const ConfigSource&)> export_mjcf;
  /// Generates a dataset; `opts.out_path` names the file.
  std::function<GenerateResult(const ConfigSource&, const GenerateOptions&)> generate;
};

/// Defaults of the `incipient` scenario: the rail config on clear acrylic with the
/// external camera, retraction 0.3 mm/s, fingerprint-v2 skin.
RailScenarioConfig IncipientDefaults();

/// All registered scenarios, in listing order.
const std::vector<ScenarioEntry>& Scenarios();
/// The scenario named `name`; throws InputError listing the known names.
const ScenarioEntry& FindScenario(const std::string& name);

}  // namespace tactip
