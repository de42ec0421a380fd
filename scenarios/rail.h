#pragma once
// The rail protocol: press the TacTip normal to the stimulus, lift the object 50 mm
// by friction alone, retract at constant speed until the object falls.

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>

#include "models/rail_rig.h"
#include "sensors/camera.h"
#include "sensors/dataset.h"
#include "sensors/labels.h"
#include "sim/sim_config.h"

namespace tactip {

/// Full configuration of the rail scenario; every field is documented in its section.
struct RailScenarioConfig {
  SimConfig sim;
  ObjectConfig object;
  ContactConfig contact;
  RailConfig rail;
  SkinConfig skin;
  ArmConfig arm;
  CameraConfig sensor;
  ExternalCameraConfig external;
  LabelConfig labels;

  template <class V>
  void Visit(V& v) {
    v.Section("sim", sim);
    v.Section("object", object);
    v.Section("contact", contact);
    v.Section("rail", rail);
    v.Section("skin", skin);
    v.Section("arm", arm);
    v.Section("sensor", sensor);
    v.Section("external", external);
    v.Section("labels", labels);
  }
  /// Cross-field rules, including the timestep stability limit of the built model.
  void ValidateRules() const;
  /// The scene spec for this config (deepest press includes the depth jitter).
  RailSceneSpec SceneSpec() const;
};

/// Run-level results beyond the arrays, also stored as run attributes.
struct RailRunSummary {
  double gross_slip_onset_s = 0.0;   ///< first gross-slip frame after the lift (NaN: none)
  double incipient_onset_s = 0.0;    ///< first partial-slip frame after retraction starts, before gross slip (NaN: none)
  double incipient_lead_s = 0.0;     ///< gross_slip_onset_s - incipient_onset_s (NaN: either missing)
  double pre_slip_fraction = 0.0;    ///< pins in contact at retraction start that slid before gross slip
  double object_fall_s = 0.0;        ///< object dropped fall_threshold_mm (NaN: never)
  double predicted_onset_s = 0.0;    ///< Coulomb: mu*sum(N) + rail friction falls below m g
  double coulomb_early_s = 0.0;      ///< mu*sum(N) - rail friction falls below m g (earliest skin slip)
  double retract_start_s = 0.0;      ///< retraction begins
  double creep_um = 0.0;             ///< object sliding relative to the centre pin before onset
  double press_depth_mm = 0.0;       ///< this run's depth (with jitter)
  double friction = 0.0;             ///< this run's friction coefficient (with jitter)
  double sim_time_s = 0.0;           ///< simulated time
  double wall_time_s = 0.0;          ///< wall-clock time of the run
  long long steps = 0;               ///< physics steps
  int mujoco_warnings = 0;           ///< warnings MuJoCo raised (a run with any stops early)
  bool held = true;                  ///< false: the object slipped before the retraction started
};

/// Set to true (e.g. by a signal handler) to stop running runs with an InputError-free
/// `Interrupted` exception.
class Interrupted : public std::runtime_error {
 public:
  Interrupted() : std::runtime_error("interrupted") {}
};

/// Runs rail-protocol runs of one configuration. Thread-safe: Run() may be called from
/// several threads at once (the compiled model is shared read-only).
class RailScenario {
 public:
  /// Validates the config and compiles the scene once; throws InputError/ModelError.
  explicit RailScenario(const RailScenarioConfig& cfg);
  ~RailScenario();

  /// Simulates run `index` with its seed derived from `seed`; fills `record` and
  /// returns the summary. Throws SimulationError on numerical failure and Interrupted
  /// when `*stop` becomes true.
  RailRunSummary Run(int index, std::uint64_t seed, RunRecord& record,
                     const std::atomic<bool>* stop = nullptr) const;

  /// The MJCF text of the scene this scenario simulates.
  const std::string& xml() const;
  const RailScenarioConfig& config() const { return cfg_; }
  int n_pins() const;
  int n_collidable() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  RailScenarioConfig cfg_;
};

/// Options of a dataset generation.
struct GenerateOptions {
  int runs = 4;                   ///< number of runs
  std::uint64_t seed = 1;         ///< master seed
  int jobs = 0;                   ///< worker threads (0 = hardware concurrency)
  std::string out_path;           ///< output HDF5 file
  std::string scenario = "rail";  ///< name stored in the file
  /// Called after each run with (runs done, runs total, run index, summary).
  std::function<void(int, int, int, const RailRunSummary&)> progress;
  const std::atomic<bool>* stop = nullptr;  ///< cooperative interruption flag
};

/// Totals of a generation.
struct GenerateResult {
  int runs = 0;
  double sim_time_s = 0.0;
  double wall_time_s = 0.0;
};

/// Simulates runs 0..runs-1 of `scenario` on `jobs` threads (0 = all cores) and hands each
/// record to `take` in run order, on the calling thread. Rethrows the first failure;
/// throws Interrupted when `*stop` becomes true.
void RunRailRuns(const RailScenario& scenario, int runs, std::uint64_t seed, int jobs, const std::atomic<bool>* stop,
                 const std::function<void(RunRecord&&, const RailRunSummary&)>& take);

/// Simulates `opts.runs` runs in parallel and writes them, in run order, to an HDF5
/// file (atomically). Same seed and config give a bit-identical file for any `jobs`.
GenerateResult GenerateRailDataset(const RailScenarioConfig& cfg, const GenerateOptions& opts);

}  // namespace tactip
