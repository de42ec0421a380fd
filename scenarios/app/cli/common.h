#pragma once
// Helpers shared by the subcommands of `tactip`: number formatting, run attributes, the
// options that pick a scenario config, and the dataset summary.

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "scenarios/registry.h"
#include "sensors/dataset.h"

namespace tactip::cli {

/// `v` formatted with `spec`, or "-" when it is NaN (an event that did not happen).
std::string Fmt(double v, const char* spec = "{:.3f}");

/// A run attribute, NaN when absent.
double Attr(const RunRecord& r, const std::string& key);

/// The options that choose a scenario and its config: scenario name, --config, --set and
/// the shortcuts (--speed-mm-s, --stimulus, --skin, --camera).
struct ConfigArgs {
  std::string scenario;            ///< scenario name
  std::string config_path;         ///< --config YAML file
  std::vector<std::string> sets;   ///< --set KEY=VALUE, in order
  double speed_mm_s = std::nan("");///< --speed-mm-s (NaN: not given)
  std::string stimulus;            ///< --stimulus
  std::string skin;                ///< --skin preset
  std::string camera;              ///< --camera preset
  bool auto_timestep = false;      ///< --auto-timestep
  bool images = false;             ///< --images

  /// Registers the options on `c`, with the scenario as a required positional unless
  /// `with_scenario` is false.
  void Add(CLI::App* c, bool with_scenario = true);
  /// Registers --config and --set on `c`, with these help texts.
  void AddFileAndSets(CLI::App* c, const std::string& config_help, const std::string& set_help);
  /// Registers --skin on `c`, with this help text.
  void AddSkin(CLI::App* c, const std::string& help);
  /// Registers --camera on `c`.
  void AddCamera(CLI::App* c);
  /// Registers --images on `c` (shorthand for --set images.enabled=true).
  void AddImages(CLI::App* c);
  /// Registers --auto-timestep on `c`.
  void AddAutoTimestep(CLI::App* c);
  /// The config source: file, skin preset, camera preset, shortcuts (--images among them),
  /// then --set in order.
  ConfigSource Source() const;
};

/// Resolves `src` for `scenario` (which validates it) and, when it asks for --auto-timestep,
/// prints the chosen step and what binds it on stderr.
void CheckAndReport(const Scenario& scenario, const ConfigSource& src);
/// The same for a rail-protocol scenario (RailFamily refuses another), returning its config.
RailScenarioConfig ResolveRailAndReport(const Scenario& scenario, const ConfigSource& src);

/// Registers --sensor NAME on `c` into `sensor`: which sensor of a dataset to read pins from
/// (empty: the dataset's first).
CLI::Option* AddSensorOption(CLI::App* c, std::string& sensor);

/// Prints a dataset's header, its sensors, one line per run, totals and (optionally) the
/// stored config.
void PrintDatasetSummary(const std::string& path, bool with_config);

/// True when run health flagged the run (health_ok = 0); false for a healthy run and for
/// files written before run health.
bool FlaggedByHealth(const RunRecord& r);

/// The runs (all of the dataset's, or those of `runs` it has) that run health flagged
/// (health_ok = 0), ascending. Files written before run health have none.
std::vector<int> FlaggedRuns(const DatasetReader& reader, const std::vector<int>& runs = {});

/// For a command that reads the runs `runs` (empty: all) of the HDF5 dataset `path`: one
/// line on stderr when any of them is flagged by run health, saying how many, which, and
/// that their ground truth is not to be trusted. Nothing for a CSV recording or when no
/// run is flagged.
void NoteFlaggedRuns(const std::string& path, const std::vector<int>& runs = {});
/// The same for a dataset already open as `reader` (`path` names it in the line).
void NoteFlaggedRuns(const DatasetReader& reader, const std::string& path, const std::vector<int>& runs = {});

}  // namespace tactip::cli
