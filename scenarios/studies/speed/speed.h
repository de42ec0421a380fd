#pragma once
// The speed study (`tactip bench --speed`): for each scene, one run on one core with every
// step's stages timed, its real-time factor, the cost split (MuJoCo's collision,
// constraint making and projection, solve; tactip's friction plane and pass; the
// scenario's own per-step work), and the same motion replayed with bare mj_step on the
// same exported model, measured in the same process.

#include <cstdint>
#include <string>
#include <vector>

#include "scenarios/rail/rail.h"
#include "sim/step_profile.h"

namespace tactip {

/// A scene of the speed study: a registered scenario and overrides.
struct SpeedScene {
  std::string name;                    ///< e.g. "rail flat (smooth)"
  std::string scenario;                ///< registered scenario
  std::vector<std::string> overrides;  ///< "key=value"
};

/// The study's scenes: the rail scene on each stimulus with the smooth skin, the incipient
/// scene with fingerprint-v2, and the rail scene with MuJoCo's own noslip for comparison.
std::vector<SpeedScene> SpeedScenes();

/// One scene's figures.
struct SpeedRow {
  SpeedScene scene;
  double sim_s = 0.0;        ///< simulated time of the run
  double run_wall_s = 0.0;   ///< wall time of the whole run (physics and the scenario's work)
  double bare_wall_s = 0.0;  ///< the same steps (held, then sliding) with bare mj_step on the exported model
  StepProfile profile;       ///< the run's physics steps, stage by stage
  int nv = 0;                ///< dofs
  long long memory_bytes = 0;///< model + one mjData
  /// Real-time factors: whole run, physics steps alone, bare mj_step.
  double rtf_run() const { return sim_s / run_wall_s; }
  double rtf_physics() const { return sim_s / profile.total_s(); }
  double rtf_bare() const { return sim_s / bare_wall_s; }
  /// The scenario's own per-step work over the physics step: run / physics - 1.
  double overhead() const { return run_wall_s / profile.total_s() - 1.0; }
  /// Mean constraint rows and contacts per step.
  double nefc_mean() const;
  double ncon_mean() const;
  /// Mean MuJoCo solver iterations per step.
  double solver_iter_mean() const;
};

/// The scenes named (empty: all), in that order. Throws InputError for an unknown name.
std::vector<SpeedScene> ChooseSpeedScenes(const std::vector<std::string>& names);

/// The config of a speed scene: its scenario's defaults, the scene's overrides, then
/// `overrides`. Throws InputError.
RailScenarioConfig LoadSpeedScene(const SpeedScene& scene, const std::vector<std::string>& overrides);

/// Measures run 0 of `scenario` (seed `seed`) on this thread: every step timed, the same
/// controls replayed with bare mj_step, nv and memory. MuJoCo's own stage timers need
/// EnableMujocoTimers() first. `scene` names the row.
SpeedRow MeasureRailRun(const SpeedScene& scene, const RailScenario& scenario, std::uint64_t seed);

/// Measures every scene in `names` (empty: all) with `overrides` applied on top;
/// single-threaded, one run each. Throws InputError for an unknown scene name.
std::vector<SpeedRow> MeasureSpeed(const std::vector<std::string>& names, const std::vector<std::string>& overrides,
                                   std::uint64_t seed);

/// The table printed by `tactip bench --speed`.
std::string FormatSpeedTable(const std::vector<SpeedRow>& rows);
/// The same as CSV (one row per scene).
std::string SpeedCsv(const std::vector<SpeedRow>& rows);

}  // namespace tactip
