#pragma once
// Many rail runs in parallel, handed over in run order, and written as one dataset.

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "scenarios/rail/rail_scenario.h"

namespace tactip {

/// Options of a dataset generation.
struct GenerateOptions {
  int runs = 4;                   ///< number of runs of the whole job
  /// Only this shard's runs (its runs_total must equal `runs`); the file then records
  /// the shard for `tactip merge`. Unset: all runs.
  std::optional<ShardSpec> shard;
  std::uint64_t seed = 1;         ///< master seed
  int jobs = 0;                   ///< worker threads (0 = hardware concurrency)
  std::string out_path;           ///< output HDF5 file
  std::string scenario = "rail";  ///< name stored in the file
  /// Called after each run with (runs done, runs to do, run index, summary).
  std::function<void(int, int, int, const RailRunSummary&)> progress;
  const std::atomic<bool>* stop = nullptr;  ///< cooperative interruption flag
};

/// Totals of a generation.
struct GenerateResult {
  int runs = 0;
  double sim_time_s = 0.0;
  double wall_time_s = 0.0;
};

/// Simulates runs first..first+runs-1 of `scenario` on `jobs` threads (0 = all cores) and
/// hands each record to `take` in run order, on the calling thread; `make`, if set, gives
/// each run its controller (closed loop). Rethrows the first
/// failure; throws Interrupted when `*stop` becomes true.
void RunRailRuns(const RailScenario& scenario, int first, int runs, std::uint64_t seed, int jobs,
                 const std::atomic<bool>* stop, const std::function<void(RunRecord&&, const RailRunSummary&)>& take,
                 const ControllerFactory& make = {});

/// Simulates `opts.runs` runs (or the shard's block of them) in parallel and writes them,
/// in run order, to an HDF5 file (atomically). Same seed and config give a bit-identical
/// file for any `jobs`, and a shard's runs are bit-identical to the same runs of the
/// whole job.
GenerateResult GenerateRailDataset(const RailScenarioConfig& cfg, const GenerateOptions& opts);

}  // namespace tactip
