#include "scenarios/app/viewer/stored_run.h"

#include <algorithm>

#include <fmt/format.h>

#include "scenarios/registry.h"
#include "sensors/slip_data.h"

namespace tactip {

namespace {

// The stored config text applied to the defaults (it holds every key), and checked.
RailScenarioConfig StoredConfig(const std::string& path, const DatasetHeader& header) {
  try {
    return StoredRailConfig(header);
  } catch (const InputError& e) {
    throw InputError(fmt::format("--replay {}: {}", path, e.what()));
  }
}

}  // namespace

StoredRun ReadStoredRun(const std::string& path, int index) {
  const DatasetReader reader(path);
  const std::vector<int>& runs = reader.run_indices();
  if (!std::binary_search(runs.begin(), runs.end(), index)) {
    throw InputError(fmt::format("--run {}: {} has no run {} (it has {})", index, path, index, RunsText(runs)));
  }
  StoredRun stored;
  stored.path = path;
  stored.header = reader.header();
  stored.config = StoredConfig(path, stored.header);
  stored.record = reader.ReadRun(index);
  return stored;
}

}  // namespace tactip
