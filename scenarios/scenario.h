#pragma once
// A scenario as the generic commands see it (`tactip scenarios`, `config`, `export-mjcf`,
// `generate`): a name, a description and the operations that take a ConfigSource. Each
// scenario owns its config type (ConfiguredScenario, configured_scenario.h); the registry
// (registry.h) holds them as this interface.

#include <optional>
#include <string>
#include <vector>

#include "scenarios/rail/rail_generate.h"
#include "sim/config.h"

namespace tactip {

/// How a scenario is configured from the command line: a YAML file and key=value
/// overrides applied in order on top of the scenario's defaults.
struct ConfigSource {
  std::string yaml_path;               ///< empty: defaults only
  std::vector<std::string> overrides;  ///< "key=value", applied after the file
  /// Choose the timestep (for the rail protocol: sim.timestep_s by ChooseTimestep) after the
  /// file and the overrides (the step they configure is the upper cap), before the config is
  /// validated.
  bool auto_timestep = false;
};

/// A registered scenario. Every operation resolves the config from its ConfigSource first
/// (defaults, file, overrides, validation) and throws InputError when it is refused.
class Scenario {
 public:
  Scenario(std::string name, std::string description)
      : name_(std::move(name)), description_(std::move(description)) {}
  virtual ~Scenario() = default;
  Scenario(const Scenario&) = delete;
  Scenario& operator=(const Scenario&) = delete;

  /// Command-line name.
  const std::string& name() const { return name_; }
  /// One line for `tactip scenarios`.
  const std::string& description() const { return description_; }

  /// Resolves and validates the config; returns the step chosen when `src.auto_timestep` is set.
  virtual std::optional<TimestepChoice> Check(const ConfigSource& src) const = 0;
  /// Documentation of every config field, with the values `src` resolves to.
  virtual std::vector<FieldDoc> Describe(const ConfigSource& src) const = 0;
  /// The MJCF of the scene the scenario builds for this config.
  virtual std::string ExportMjcf(const ConfigSource& src) const = 0;
  /// Generates a dataset; `opts.out_path` names the file.
  virtual GenerateResult Generate(const ConfigSource& src, const GenerateOptions& opts) const = 0;

 private:
  std::string name_;
  std::string description_;
};

}  // namespace tactip
