#pragma once
// The rail protocol as registered scenarios: one class owning RailScenarioConfig, registered
// twice with different defaults (`rail` and `incipient`), and the accessor the rail-protocol
// commands (rail-catch, incipient-stop, accuracy, stability, bench, sweep, view) reach the
// config through.

#include <memory>
#include <string>

#include "scenarios/configured_scenario.h"
#include "scenarios/rail/rail_config.h"
#include "scenarios/rail/rail_generate.h"

namespace tactip {

/// Any scenario whose config is the rail protocol's.
using RailFamilyScenario = ConfiguredScenario<RailScenarioConfig>;

/// A scenario running the rail protocol from its own defaults.
class RailProtocolScenario final : public RailFamilyScenario {
 public:
  using RailFamilyScenario::RailFamilyScenario;

  std::string SceneMjcf(const RailScenarioConfig& cfg) const override;
  GenerateResult GenerateDataset(const RailScenarioConfig& cfg, const GenerateOptions& opts) const override;

 protected:
  /// ChooseTimestep, written into cfg.sim.timestep_s.
  TimestepChoice ChooseStep(RailScenarioConfig& cfg) const override;
};

/// Defaults of the `incipient` scenario: the rail config on clear acrylic with the
/// external camera, retraction 0.3 mm/s, fingerprint-v2 skin.
RailScenarioConfig IncipientDefaults();

/// The `rail` scenario: the rail config's own defaults.
std::unique_ptr<Scenario> MakeRailScenario();
/// The `incipient` scenario: IncipientDefaults().
std::unique_ptr<Scenario> MakeIncipientScenario();

/// `scenario` as a rail-protocol scenario; throws InputError "scenario 'X' has no rail
/// protocol" when its config is another type.
const RailFamilyScenario& RailFamily(const Scenario& scenario);

}  // namespace tactip
