#pragma once
// The accuracy study (`tactip accuracy`): runs a scene at every numerical setting, and for
// each reports the error against the finest (reference) setting and against the analytic
// anchors, next to the wall time per simulated second.

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "scenarios/studies/accuracy/settings.h"
#include "scenarios/registry.h"

namespace tactip {

/// Options of an accuracy study.
struct AccuracyOptions {
  std::string scene = "rail";       ///< rail, incipient (a registered scenario) or domes
  ConfigSource base;                ///< the scene's config (file, --skin/--stimulus, --set)
  int runs = 2;                     ///< runs per setting (rail, incipient), same seeds for all
  std::uint64_t seed = 1;           ///< master seed
  int jobs = 0;                     ///< worker threads (0: all cores)
  std::vector<std::string> only;    ///< setting labels to run (empty: all); the reference always runs
  const std::atomic<bool>* stop = nullptr;
  /// Called after each setting with (done, total, row).
  std::function<void(int, int, const struct AccuracyRow&)> progress;
};

/// One setting's figures. Errors are NaN when they do not apply (and inf when the reference
/// has an event the setting lacks, or the other way round).
struct AccuracyRow {
  AccuracySetting setting;
  std::string outcome = "ok";         ///< ok, or the refusal / failure message
  bool healthy = true;                ///< every run's health ok
  double wall_s_per_sim_s = 0.0;      ///< wall time per simulated second, one core
  double onset_error_ms = 0.0;        ///< |gross onset - reference's|, mean over runs
  double incipient_error_ms = 0.0;    ///< |incipient onset - reference's|, mean over runs
  double traj_rms_px = 0.0;           ///< pin trajectories against the reference's, RMS
  double creep_um = 0.0;              ///< largest creep before the onset of any run
  double label_disagreement_pct = 0.0;///< pin-frames whose labels differ from the reference's, %
  int flicker_max = 0;                ///< most contact on/off transitions of a pin while held
  double coulomb_error_ms = 0.0;      ///< anchor: |onset - Coulomb prediction|, mean over runs
  // Domes: the exact quasi-static solution and Cattaneo-Mindlin are the anchors.
  double release_error = 0.0;         ///< domes: mean |release load - exact| over pins and domes, Q / mu P
  double gross_error = 0.0;           ///< domes: largest |gross slip load / mu P - 1|
  double band_fraction = 0.0;         ///< domes: continuum dome's stick boundary in the CM-brush band
  double band_error = 0.0;            ///< domes: |band fraction - reference's|
};

/// The whole study.
struct AccuracyReport {
  std::string scene, config_note;  ///< what was run
  std::vector<AccuracyRow> rows;   ///< reference first
};

/// The settings the study of `opts.scene` sweeps (the reference first), for the scene's
/// config: the rail-protocol scenes' timesteps are relative to the configured step.
std::vector<AccuracySetting> AccuracySettings(const AccuracyOptions& opts);

/// Throws InputError naming the problem when the scene, a setting or the reference's config
/// is bad (RunAccuracy checks this too; callers use it before printing anything).
void CheckAccuracyOptions(const AccuracyOptions& opts);

/// Runs the study; throws InputError for a bad scene or setting, Interrupted on stop.
AccuracyReport RunAccuracy(const AccuracyOptions& opts);

/// The table printed on stdout.
std::string FormatAccuracyTable(const AccuracyReport& report);
/// One CSV row per setting (the columns of AccuracyRow, plus is_default, is_reference).
std::string AccuracyCsv(const AccuracyReport& report);
/// The error columns of the scene's CSV, for the plot's panels.
std::vector<std::string> AccuracyErrorColumns(const std::string& scene);

}  // namespace tactip
