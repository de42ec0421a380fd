#pragma once
// The rail protocol: press the TacTip normal to the stimulus, lift the object 50 mm by
// friction alone, retract at constant speed until the object falls.

#include <atomic>
#include <cstdint>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "scenarios/rail/rail_config.h"
#include "scenarios/rail/rail_controller.h"
#include "scenarios/rail/run_health.h"
#include "sensors/dataset.h"
#include "sim/simulation.h"
#include "sim/step_profile.h"

namespace tactip {

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
  RunHealth health;                  ///< run health figures and verdict
  std::vector<ControllerAction> actions;  ///< what the run's controller did
  std::map<std::string, double> controller_figures;  ///< what it measured (RailController::Figures)
};

/// Thrown by a run when its stop flag becomes true (Ctrl-C).
class Interrupted : public std::runtime_error {
 public:
  Interrupted() : std::runtime_error("interrupted") {}
};

struct RailSceneIds;

/// What a speed measurement takes from one run: the step's cost split and the actuator
/// controls of every step (to replay the same motion with bare mj_step).
struct RunInstrumentation {
  StepProfile profile;
  std::vector<double> ctrl;        ///< nu values per step
  std::vector<double> timestep_s;  ///< each step's length (the sliding step from the gross-slip onset)
};

/// Runs rail-protocol runs of one configuration. Thread-safe: Run() may be called from
/// several threads at once (the compiled model is shared read-only).
class RailScenario {
 public:
  /// Validates the config and compiles the scene once; throws InputError/ModelError.
  explicit RailScenario(const RailScenarioConfig& cfg);
  /// The same with parts of the scene put back that the runs do not need (for measuring
  /// what leaving them out saves; see SceneOptions).
  RailScenario(const RailScenarioConfig& cfg, const SceneOptions& options);
  ~RailScenario();

  /// Simulates run `index` with its seed derived from `seed`; fills `record` and
  /// returns the summary. Throws SimulationError on numerical failure and Interrupted
  /// when `*stop` becomes true.
  RailRunSummary Run(int index, std::uint64_t seed, RunRecord& record,
                     const std::atomic<bool>* stop = nullptr) const;
  /// The same run with the arm driven by the controller `make` returns for it (closed loop).
  RailRunSummary Run(int index, std::uint64_t seed, RunRecord& record, const std::atomic<bool>* stop,
                     const ControllerFactory& make) const;
  /// The same run, timing every stage of every step and recording the controls.
  RailRunSummary RunInstrumented(int index, std::uint64_t seed, RunRecord& record, RunInstrumentation& out) const;
  /// The compiled scene (shared read-only by the runs).
  const CompiledModel& model() const;

  /// The MJCF text of the scene this scenario simulates.
  const std::string& xml() const;
  const RailScenarioConfig& config() const { return cfg_; }
  int n_pins() const;
  int n_collidable() const;

 private:
  std::unique_ptr<RailSceneIds> ids_;
  RailScenarioConfig cfg_;
};

}  // namespace tactip
