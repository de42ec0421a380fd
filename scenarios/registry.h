#pragma once
// The one place where scenarios are named. The command line lists and runs them through
// this registry; each is a Scenario owning its config type (scenario.h,
// configured_scenario.h), the rail protocol's in scenarios/rail/.

#include <memory>
#include <string>
#include <vector>

#include "scenarios/rail/rail_protocol_scenario.h"
#include "scenarios/scenario.h"
#include "sensors/dataset.h"

namespace tactip {

/// All registered scenarios, in listing order.
const std::vector<std::unique_ptr<Scenario>>& Scenarios();
/// The scenario named `name`; throws InputError listing the known names.
const Scenario& FindScenario(const std::string& name);

/// The config a dataset of a rail-protocol scenario was written with: its stored config
/// text applied to the defaults (it holds every key), and checked. Throws InputError.
RailScenarioConfig StoredRailConfig(const DatasetHeader& header);

}  // namespace tactip
