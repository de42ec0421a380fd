#include "scenarios/registry.h"

#include "sim/base/errors.h"

namespace tactip {

namespace {

std::vector<std::unique_ptr<Scenario>> MakeScenarios() {
  std::vector<std::unique_ptr<Scenario>> all;
  all.push_back(MakeRailScenario());
  all.push_back(MakeIncipientScenario());
  return all;
}

}  // namespace

const std::vector<std::unique_ptr<Scenario>>& Scenarios() {
  static const std::vector<std::unique_ptr<Scenario>> all = MakeScenarios();
  return all;
}

const Scenario& FindScenario(const std::string& name) {
  std::string known;
  for (const auto& s : Scenarios()) {
    if (s->name() == name) return *s;
    known += (known.empty() ? "" : ", ") + s->name();
  }
  throw InputError("unknown scenario '" + name + "' (known: " + known + ")");
}

RailScenarioConfig StoredRailConfig(const DatasetHeader& header) {
  RailFamily(FindScenario(header.scenario));
  RailScenarioConfig cfg;
  ApplyFlat(cfg, FlattenYaml(header.config_yaml, "its root attribute config_yaml"));
  ValidateConfig(cfg);
  return cfg;
}

}  // namespace tactip
