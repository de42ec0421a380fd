#pragma once
// What drives the arm of a rail run: a scene controller (scene_controller.h) whose controls
// are the arm's two servo targets. The offline protocol (press, lift, hold, retract) is the
// controller that follows RailSchedule and ignores the frames; closed-loop protocols (catch,
// stop) run a detector on the frames and change the targets.

#include <functional>
#include <memory>
#include <span>

#include "scenarios/rail/rail_schedule.h"
#include "scenarios/scene/scene_controller.h"

namespace tactip {

/// The arm's servo targets (m): x along the stimulus normal (towards it) from the start
/// pose, z up.
struct ArmTargets {
  double x_m = 0.0;
  double z_m = 0.0;
};

/// Drives the arm of one rail run. One instance per run.
class RailController : public SceneController {
 public:
  /// The servo targets at simulated time t (asked at every step).
  virtual ArmTargets Targets(double t) = 0;
  /// The rail scene's controls, in its actuator order: the x servo's target, then the z servo's.
  void Controls(double t, std::span<double> out) final {
    const ArmTargets a = Targets(t);
    out[0] = a.x_m;
    out[1] = a.z_m;
  }
  /// The latest time the run may last (s): the protocol's give-up time unless the
  /// controller retracts more slowly.
  virtual double GiveUpTime(const RailSchedule& schedule) const { return schedule.give_up; }
  /// How far past the protocol's deepest press the controller may drive the sensor in (m);
  /// the run's plausibility limits (StateLimits) allow for it.
  virtual double ExtraPressM() const { return 0.0; }
};

/// Makes the controller of run `index` for that run's timeline (an empty factory: the
/// offline protocol).
using ControllerFactory = std::function<std::unique_ptr<RailController>(int index, const RailSchedule& schedule)>;

/// The offline protocol: RailSchedule's timeline, frames ignored.
class ScheduleController : public RailController {
 public:
  explicit ScheduleController(const RailSchedule& schedule) : schedule_(schedule) {}
  ArmTargets Targets(double t) override { return {schedule_.X(t), schedule_.Z(t)}; }

 private:
  const RailSchedule schedule_;
};

}  // namespace tactip
