#pragma once
// A scenario that owns a config struct (a `Visit` struct of sim/config.h): its defaults, and
// the generic operations of Scenario done on the config it loads. A scenario with another
// config type derives from ConfiguredScenario<ItsConfig>; commands that need the config
// itself reach it with ConfiguredAs<ItsConfig>.

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "scenarios/scenario.h"
#include "sim/base/errors.h"
#include "sim/config.h"

namespace tactip {

/// A config as resolved from a ConfigSource.
template <class Config>
struct Resolved {
  Config config;                          ///< validated
  std::optional<TimestepChoice> timestep; ///< the step chosen (ConfigSource::auto_timestep)
};

template <class Config>
class ConfiguredScenario : public Scenario {
 public:
  ConfiguredScenario(std::string name, std::string description, Config defaults)
      : Scenario(std::move(name), std::move(description)), defaults_(std::move(defaults)) {}

  /// The config before any file or override.
  const Config& defaults() const { return defaults_; }

  /// Defaults, file and overrides; then the chosen timestep, if asked for; then every rule
  /// (throws InputError).
  Resolved<Config> Resolve(const ConfigSource& src) const {
    Resolved<Config> r{ApplyConfig(src.yaml_path, src.overrides, defaults_), std::nullopt};
    if (src.auto_timestep) r.timestep = ChooseStep(r.config);
    ValidateConfig(r.config);
    return r;
  }
  /// The resolved, validated config (throws InputError).
  Config Load(const ConfigSource& src) const { return Resolve(src).config; }

  std::optional<TimestepChoice> Check(const ConfigSource& src) const final { return Resolve(src).timestep; }
  std::vector<FieldDoc> Describe(const ConfigSource& src) const final { return DescribeConfig(Load(src)); }
  std::string ExportMjcf(const ConfigSource& src) const final { return SceneMjcf(Load(src)); }
  GenerateResult Generate(const ConfigSource& src, const GenerateOptions& opts) const final {
    return GenerateDataset(Load(src), opts);
  }

  /// The MJCF of the scene built for `cfg`.
  virtual std::string SceneMjcf(const Config& cfg) const = 0;
  /// Generates a dataset of `cfg`'s runs.
  virtual GenerateResult GenerateDataset(const Config& cfg, const GenerateOptions& opts) const = 0;

 protected:
  /// Sets `cfg`'s timestep for ConfigSource::auto_timestep and says what bounds it. A config
  /// without a timestep rule refuses it.
  virtual TimestepChoice ChooseStep(Config& cfg) const {
    (void)cfg;
    throw InputError("--auto-timestep: scenario '" + name() + "' has no timestep rule; set its step in the config");
  }

 private:
  Config defaults_;
};

/// `scenario` as the scenario of config type `Config`, or nullptr when its config is another.
template <class Config>
const ConfiguredScenario<Config>* ConfiguredAs(const Scenario& scenario) {
  return dynamic_cast<const ConfiguredScenario<Config>*>(&scenario);
}

}  // namespace tactip
