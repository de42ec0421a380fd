#pragma once
// What drives the arm of a rail run. At every step the run asks its controller for the
// servo targets; at every camera frame it shows the controller what each tactile sensor's
// camera delivered. The offline protocol (press, lift, hold, retract) is the controller
// that follows RailSchedule and ignores the frames; closed-loop protocols (catch, stop)
// run a detector on the frames and change the targets.

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "detectors/pin_frame.h"
#include "scenarios/rail/rail_schedule.h"
#include "sensors/dataset.h"  // ControllerAction

namespace tactip {

/// The arm's servo targets (m): x along the stimulus normal (towards it) from the start
/// pose, z up.
struct ArmTargets {
  double x_m = 0.0;
  double z_m = 0.0;
};

/// What a controller sees at one camera frame.
struct FrameInput {
  double time_s = 0.0;                   ///< frame time (s)
  std::vector<const PinFrame*> frames;   ///< one per tactile sensor, in scene order
};

/// Drives the arm of one rail run. One instance per run.
class RailController {
 public:
  virtual ~RailController() = default;
  /// The servo targets at simulated time t (asked at every step).
  virtual ArmTargets Targets(double t) = 0;
  /// Called at each camera frame once every sensor has captured it.
  virtual void OnFrame(const FrameInput& input) {}
  /// True when the controller's trial is over and the run may end at time t.
  virtual bool Done(double t) const { return false; }
  /// The latest time the run may last (s): the protocol's give-up time unless the
  /// controller retracts more slowly.
  virtual double GiveUpTime(const RailSchedule& schedule) const { return schedule.give_up; }
  /// How far past the protocol's deepest press the controller may drive the sensor in (m);
  /// the run's plausibility limits (StateLimits) allow for it.
  virtual double ExtraPressM() const { return 0.0; }
  /// What the controller did so far.
  virtual std::vector<ControllerAction> Actions() const { return {}; }
  /// Figures the controller measured (e.g. classification time), by name.
  virtual std::map<std::string, double> Figures() const { return {}; }
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
