#pragma once
// The rail protocol (scenarios `rail` and `incipient`): its config, one run, and dataset
// generation. The parts live in scenarios/rail/.

#include "scenarios/rail/rail_config.h"
#include "scenarios/rail/rail_generate.h"
#include "scenarios/rail/rail_scenario.h"
