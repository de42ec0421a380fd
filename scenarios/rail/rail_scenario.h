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
#include "scenarios/scene/scene_run.h"
#include "scenarios/scene/run_health.h"
#include "sensors/dataset.h"
#include "sim/base/errors.h"
#include "sim/simulation.h"
#include "sim/step_profile.h"

namespace tactip {

/// The events of a rail run (SceneRunSummary: the object on the rail and its sensors) and
/// the protocol's own figures, also stored as run attributes.
struct RailRunSummary : SceneRunSummary {
  double retract_start_s = 0.0;      ///< retraction begins
  double press_depth_mm = 0.0;       ///< this run's depth (with jitter)
  double friction = 0.0;             ///< this run's friction coefficient (with jitter)
};

struct RailScene;

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
  std::unique_ptr<RailScene> scene_;
  RailScenarioConfig cfg_;
};

}  // namespace tactip
