#pragma once
// A run stored in a dataset, with what re-simulating it takes: the file's scenario, config
// and seed.

#include <string>

#include "scenarios/rail/rail_config.h"
#include "sensors/dataset.h"

namespace tactip {

/// One stored run and how it was made.
struct StoredRun {
  std::string path;           ///< the dataset file
  DatasetHeader header;       ///< its scenario, seed and config text
  RailScenarioConfig config;  ///< the config the file stores, validated
  RunRecord record;           ///< the run as stored
};

/// Reads run `index` of the dataset `path` and its config. Throws InputError in one line
/// when the file cannot be read, has no run `index` (naming the runs it has), names a
/// scenario this program does not know, or stores a config that does not load.
StoredRun ReadStoredRun(const std::string& path, int index);

}  // namespace tactip
