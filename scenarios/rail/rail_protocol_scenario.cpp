#include "scenarios/rail/rail_protocol_scenario.h"

#include <vector>

#include "models/rail_rig.h"

namespace tactip {

std::string RailProtocolScenario::SceneMjcf(const RailScenarioConfig& cfg) const {
  return BuildRailScene(cfg.SceneSpec()).xml;
}

GenerateResult RailProtocolScenario::GenerateDataset(const RailScenarioConfig& cfg,
                                                     const GenerateOptions& opts) const {
  return GenerateRailDataset(cfg, opts);
}

TimestepChoice RailProtocolScenario::ChooseStep(RailScenarioConfig& cfg) const {
  const TimestepChoice choice = ChooseTimestep(cfg);
  cfg.sim.timestep_s = choice.timestep_s;
  return choice;
}

RailScenarioConfig IncipientDefaults() {
  // The acrylic contact: per-pin friction variation and velocity weakening with a slip
  // memory (docs/model.md, "Contacts and friction"), which let partial slip spread before the
  // grip fails.
  std::vector<std::string> keys = {"rail.stimulus=acrylic",           "external.enabled=true",
                                   "rail.retract_speed_mm_s=0.3",     "contact.pin_friction_spread=0.2",
                                   "contact.weakening_speed_mm_s=1",  "contact.slip_memory_um=10",
                                   "rail.lift_speed_mm_s=5"};
  for (const auto& k : SkinPresetOverrides("fingerprint-v2")) keys.push_back(k);
  return LoadConfig<RailScenarioConfig>("", keys);
}

std::unique_ptr<Scenario> MakeRailScenario() {
  return std::make_unique<RailProtocolScenario>(
      "rail", "low-friction rail rig: press the smooth TacTip on a stimulus, lift 50 mm, retract until the object falls",
      RailScenarioConfig{});
}

std::unique_ptr<Scenario> MakeIncipientScenario() {
  return std::make_unique<RailProtocolScenario>(
      "incipient",
      "transparent-acrylic rig: the rail protocol on a clear 10 mm acrylic plate with an external camera; "
      "fingerprint-v2 skin by default (--skin smooth|fingerprint-v1|fingerprint-v2), retraction 0.3 mm/s",
      IncipientDefaults());
}

const RailFamilyScenario& RailFamily(const Scenario& scenario) {
  const RailFamilyScenario* rail = ConfiguredAs<RailScenarioConfig>(scenario);
  if (rail == nullptr) throw InputError("scenario '" + scenario.name() + "' has no rail protocol");
  return *rail;
}

}  // namespace tactip
