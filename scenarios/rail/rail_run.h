#pragma once
// One run of the rail protocol: the rail scene (scene parts: the slider carrying the
// stimulus on its rail, the arm's two servos, the TacTips) driven by the protocol's
// controller through the scene run. Internal to the rail scenarios.

#include <atomic>
#include <cstdint>
#include <memory>

#include "scenarios/rail/rail_config.h"
#include "scenarios/rail/rail_controller.h"
#include "scenarios/rail/rail_scenario.h"
#include "scenarios/rail/rail_schedule.h"
#include "scenarios/scene/scene.h"
#include "scenarios/scene/scene_run.h"

namespace tactip {

/// The rail scene of a config, compiled once and shared read-only by its runs.
struct RailScene {
  Scene scene;
  /// Builds the scene of `cfg` (with the parts `options` puts back), compiles it and looks
  /// its parts up; throws ModelError.
  RailScene(const RailScenarioConfig& cfg, const SceneOptions& options);
};

/// The limits of a physically possible frame of `cfg`'s rail runs (StateLimits::For): the
/// protocol's deepest press, the object's weight and the rail's friction as the load, with
/// `n_collidable` pins that can touch; a controller that presses `extra_press_m` deeper.
StateLimits RailStateLimits(const RailScenarioConfig& cfg, int n_collidable, double extra_press_m = 0.0);

/// One run of the rail protocol: its draws (press depth, friction), its timeline, its
/// controller and the scene run that steps it.
class RailRun {
 public:
  /// Run `index` of master seed `seed`: draws its press depth and friction from its seed and
  /// prepares its own copy of the model; `make` (empty: the offline protocol's schedule)
  /// makes the controller that drives the arm.
  RailRun(const RailScenarioConfig& cfg, const RailScene& scene, int index, std::uint64_t seed,
          const ControllerFactory& make = {});
  /// The same with the arm driven by `controller`, which must outlive the run.
  RailRun(const RailScenarioConfig& cfg, const RailScene& scene, int index, std::uint64_t seed,
          RailController& controller);

  /// Times every step's stages and records the controls into `out` (before the first step).
  void Instrument(RunInstrumentation* out) { run_->Instrument(out); }
  /// Advances one physics step (SceneRun::Step).
  bool Step(RunRecord& rec) { return run_->Step(rec); }
  /// Ends the run: the summary, also written into `rec`'s attributes with the protocol's.
  RailRunSummary Finish(RunRecord& rec);
  /// The whole protocol: Step() until the end, then Finish(); throws SimulationError, or
  /// Interrupted when `*stop` becomes true.
  RailRunSummary Execute(RunRecord& rec, const std::atomic<bool>* stop);

  /// Simulated time (s), the simulation and the sensors (for viewers).
  double time() const { return run_->time(); }
  const Simulation& simulation() const { return run_->simulation(); }
  const TactileSensor& sensor(size_t k = 0) const { return run_->sensor(k); }
  size_t sensor_count() const { return run_->sensor_count(); }
  /// The protocol's timeline for this run's press depth.
  const RailSchedule& schedule() const { return sched_; }

 private:
  // This run's draws: press depth and friction coefficient, each on its own stream.
  struct Draws {
    std::uint64_t run_seed;
    double depth_m, mu;
    double retract_speed_mm_s;  ///< this run's retraction speed
  };
  static Draws Draw(const RailScenarioConfig& cfg, std::uint64_t run_seed);
  RailRun(const RailScenarioConfig& cfg, const RailScene& scene, int index, const Draws& draws,
          const ControllerFactory& make, RailController* controller);
  void Start(const RailScene& scene, int index);

  const RailScenarioConfig& c_;
  const Draws draws_;
  const RailSchedule sched_;
  ScheduleController schedule_controller_;
  std::unique_ptr<RailController> owned_;  // the controller `make` made
  RailController* controller_;             // owned_, the caller's or schedule_controller_
  SceneRunSettings settings_;
  std::unique_ptr<SceneRun> run_;
};

}  // namespace tactip
