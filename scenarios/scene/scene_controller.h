#pragma once
// What drives a scene run. At every step the run asks its controller for one control per
// actuator of the scene; at every camera frame it shows the controller what each tactile
// sensor's camera delivered. An offline protocol is the controller that follows its
// timeline and ignores the frames; a closed-loop protocol runs a detector on the frames and
// changes the controls.

#include <map>
#include <span>
#include <string>
#include <vector>

#include "detectors/pin_frame.h"
#include "sensors/dataset.h"  // ControllerAction

namespace tactip {

/// What a controller sees at one camera frame.
struct FrameInput {
  double time_s = 0.0;                   ///< frame time (s)
  std::vector<const PinFrame*> frames;   ///< one per tactile sensor, in scene order
};

/// The phases of a protocol the run needs to know, as times (s) from the run's start.
struct ProtocolTimeline {
  double load_s = 0.0;     ///< the sensors take the object's weight from here on: the gross-slip onset is searched
  double held_s = 0.0;     ///< the object is held still from here on: run health judges the hold
  double release_s = 0.0;  ///< the grip is released from here on: incipient slip, first slips, the Coulomb prediction, the fall
  double give_up_s = 0.0;  ///< the run ends here at the latest
  double after_loss_s = 0.0;  ///< simulated time kept after the object is lost
};

/// Drives the actuators of one run. One instance per run.
class SceneController {
 public:
  virtual ~SceneController() = default;
  /// The controls at simulated time t (asked at every step; must not allocate): one per
  /// actuator of the scene, in scene order, written into `out`.
  virtual void Controls(double t, std::span<double> out) = 0;
  /// Called at each camera frame once every sensor has captured it.
  virtual void OnFrame(const FrameInput& input) {}
  /// True when the controller's trial is over and the run may end at time t.
  virtual bool Done(double t) const { return false; }
  /// What the controller did so far.
  virtual std::vector<ControllerAction> Actions() const { return {}; }
  /// Figures the controller measured (e.g. classification time), by name.
  virtual std::map<std::string, double> Figures() const { return {}; }
};

}  // namespace tactip
