#include "scenarios/registry.h"

#include "models/rail_rig.h"

namespace tactip {

namespace {

// Defaults, file and overrides; then the chosen timestep, if asked for; then every rule.
ResolvedConfig Resolve(const ConfigSource& src, const RailScenarioConfig& defaults) {
  ResolvedConfig r;
  r.config = ApplyConfig(src.yaml_path, src.overrides, defaults);
  if (src.auto_timestep) {
    r.timestep = ChooseTimestep(r.config);
    r.config.sim.timestep_s = r.timestep->timestep_s;
  }
  ValidateConfig(r.config);
  return r;
}

ResolvedConfig ResolveRail(const ConfigSource& src) { return Resolve(src, RailScenarioConfig{}); }
ResolvedConfig ResolveIncipient(const ConfigSource& src) { return Resolve(src, IncipientDefaults()); }
RailScenarioConfig LoadRail(const ConfigSource& src) { return ResolveRail(src).config; }
RailScenarioConfig LoadIncipient(const ConfigSource& src) { return ResolveIncipient(src).config; }

}  // namespace

RailScenarioConfig IncipientDefaults() {
  // The acrylic contact: per-pin friction variation and velocity weakening (README,
  // "Contacts and friction"), which let partial slip spread before the grip fails.
  std::vector<std::string> keys = {"rail.stimulus=acrylic", "external.enabled=true", "rail.retract_speed_mm_s=0.3",
                                   "contact.pin_friction_spread=0.2", "contact.weakening_speed_mm_s=1", "rail.lift_speed_mm_s=5"};
  for (const auto& k : SkinPresetOverrides("fingerprint-v2")) keys.push_back(k);
  return LoadConfig<RailScenarioConfig>("", keys);
}

const std::vector<ScenarioEntry>& Scenarios() {
  static const std::vector<ScenarioEntry> entries = {
      {"rail",
       "low-friction rail rig: press the smooth TacTip on a stimulus, lift 50 mm, retract until the object falls",
       LoadRail,
       ResolveRail,
       [](const ConfigSource& s) { return DescribeConfig(LoadRail(s)); },
       [](const ConfigSource& s) { return BuildRailScene(LoadRail(s).SceneSpec()).xml; },
       [](const ConfigSource& s, const GenerateOptions& o) { return GenerateRailDataset(LoadRail(s), o); }},
      {"incipient",
       "transparent-acrylic rig: the rail protocol on a clear 10 mm acrylic plate with an external camera; "
       "fingerprint-v2 skin by default (--skin smooth|fingerprint-v1|fingerprint-v2), retraction 0.3 mm/s",
       LoadIncipient,
       ResolveIncipient,
       [](const ConfigSource& s) { return DescribeConfig(LoadIncipient(s)); },
       [](const ConfigSource& s) { return BuildRailScene(LoadIncipient(s).SceneSpec()).xml; },
       [](const ConfigSource& s, const GenerateOptions& o) { return GenerateRailDataset(LoadIncipient(s), o); }},
  };
  return entries;
}

const ScenarioEntry& FindScenario(const std::string& name) {
  std::string known;
  for (const auto& e : Scenarios()) {
    if (e.name == name) return e;
    known += (known.empty() ? "" : ", ") + e.name;
  }
  throw InputError("unknown scenario '" + name + "' (known: " + known + ")");
}

}  // namespace tactip
