#include "scenarios/registry.h"

#include "models/rail_rig.h"

namespace tactip {

namespace {

RailScenarioConfig LoadRail(const ConfigSource& src) {
  return LoadConfig<RailScenarioConfig>(src.yaml_path, src.overrides);
}

}  // namespace

const std::vector<ScenarioEntry>& Scenarios() {
  static const std::vector<ScenarioEntry> entries = {
      {"rail",
       "low-friction rail rig: press the smooth TacTip on a stimulus, lift 50 mm, retract until the object falls",
       [](const ConfigSource& s) { return DescribeConfig(LoadRail(s)); },
       [](const ConfigSource& s) { return BuildRailScene(LoadRail(s).SceneSpec()).xml; },
       [](const ConfigSource& s, const GenerateOptions& o) { return GenerateRailDataset(LoadRail(s), o); }},
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
