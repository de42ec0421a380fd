#pragma once
// `tactip sweep`: run a scenario over a grid of config values and score each design by
// its incipient-slip figures (one CSV row per design, one PNG heatmap per metric).

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "detectors/incipient.h"
#include "scenarios/studies/incipient_report/incipient_report.h"
#include "scenarios/registry.h"
#include "scenarios/studies/sweeps/sweep_grid.h"

namespace tactip {

/// What a sweep runs.
struct SweepOptions {
  const RailFamilyScenario* scenario = nullptr;  ///< scenario whose config the grid modifies
  ConfigSource base;                        ///< YAML file and overrides applied before each design's values
  std::vector<SweepParam> params;           ///< the grid axes (first varies slowest)
  int runs = 4;                             ///< runs per design (the same seeds for every design)
  std::uint64_t seed = 1;                   ///< master seed
  int jobs = 0;                             ///< worker threads per design (0 = all cores)
  std::string out_dir;                      ///< folder for designs.csv, runs.csv and the heatmaps
  bool plots = true;                        ///< draw the heatmaps (PNG, matplotlib); false: CSVs only
  IncipientParams detector;                 ///< incipient detector parameters (hardware defaults)
  const std::atomic<bool>* stop = nullptr;  ///< cooperative interruption
  /// Called with the number of designs once every design is validated, before any runs.
  std::function<void(size_t)> started;
};

/// Result of one design.
struct SweepDesignResult {
  SweepDesign design;
  IncipientSummary summary;
  std::vector<IncipientRunMetrics> runs;
  int n_pins = 0;
  int n_collidable = 0;
  /// Time constant of the skin's collective shear mode, c_tip / k_tip (s): the joint
  /// damping a membrane lattice needs for stability at the timestep slows it (see docs/limitations.md 'Numerics').
  double shear_relaxation_s = 0.0;
  double sim_time_s = 0.0;
  double wall_time_s = 0.0;
};

/// One scored metric of a sweep (a CSV column and a heatmap `<name>.png`).
struct SweepMetric {
  std::string name;   ///< CSV column and file stem
  std::string title;  ///< heatmap title
  std::string unit;
  std::function<double(const SweepDesignResult&)> value;
};

/// The metrics written as heatmaps: incipient lead (mean, spread), fraction of pins
/// slipping before gross slip, gross-slip signal strength, detector lead and miss rate.
const std::vector<SweepMetric>& SweepMetrics();

/// True when RunSweep draws heatmaps for these options: plots on and 1 or 2 swept keys.
bool SweepDrawsHeatmaps(const SweepOptions& opts);

/// Validates every design's config first (throws InputError naming the design) and, when
/// it will draw heatmaps, checks the plotting tool (CheckPlotting: InputError before any
/// run); then runs the designs in grid order, writing `designs.csv`, `runs.csv` and one
/// heatmap per metric (`<metric>.png`, drawn by matplotlib from designs.csv) into
/// `out_dir` (created if missing). Heatmaps need 1 or 2 swept keys; with more, or with
/// opts.plots false, only the CSVs are written. A heatmap that fails after the runs throws
/// PlotError (the CSVs are already written). `progress(done, total, result)` after each
/// design.
std::vector<SweepDesignResult> RunSweep(const SweepOptions& opts,
                                        const std::function<void(int, int, const SweepDesignResult&)>& progress = {});

/// designs.csv text: the swept keys, then sizes, then every summary figure.
std::string SweepDesignsCsv(const std::vector<SweepParam>& params, const std::vector<SweepDesignResult>& results);

}  // namespace tactip
