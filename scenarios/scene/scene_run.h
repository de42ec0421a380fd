#pragma once
// One run of a scene, step by step: the controller's controls, the physics step, the
// contacts read out, the pins' friction law, per-sensor labels and the object's onsets,
// every sensor's camera frame at each frame time, run health, the controller's frame hook
// and the recording. No rig owns it: a protocol describes its scene (scene.h), its phases
// (ProtocolTimeline) and its controller (SceneController), and this loop does the rest.

#include <atomic>
#include <chrono>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "scenarios/scene/object_watch.h"
#include "scenarios/scene/run_health.h"
#include "scenarios/scene/scene.h"
#include "scenarios/scene/scene_controller.h"
#include "scenarios/scene/sensor_channel.h"
#include "scenarios/scene/step_clock.h"
#include "sensors/dataset.h"
#include "sensors/labels.h"
#include "sensors/run_recorder.h"
#include "sensors/shell_damping.h"
#include "sensors/state_limits.h"
#include "sensors/tactile_image.h"
#include "sim/sim_config.h"
#include "sim/simulation.h"
#include "sim/step_profile.h"

namespace tactip {

/// The settings of the step loop, from the scenario's config.
struct SceneRunSettings {
  SimConfig sim;               ///< the physics step and the sliding step
  ContactConfig contact;       ///< the pins' friction law
  LabelConfig labels;          ///< stick/slip labels, the object's slip speed and fall threshold
  HealthConfig health;         ///< run health thresholds
  TactileImageConfig images;   ///< rendered frames and blob tracking, when enabled
  StateLimits limits;          ///< a physically possible frame of every sensor
};

/// This run's number and draws: its seed (every noise stream derives from it) and friction.
struct RunDraws {
  int index = 0;               ///< run number
  std::uint64_t run_seed = 0;  ///< the run's seed
  double mu = 0.0;             ///< static friction coefficient of the pins against the object
};

/// What a speed measurement takes from one run: the step's cost split and the actuator
/// controls of every step (to replay the same motion with bare mj_step).
struct RunInstrumentation {
  StepProfile profile;
  std::vector<double> ctrl;        ///< nu values per step
  std::vector<double> timestep_s;  ///< each step's length (the sliding step from the gross-slip onset)
};

/// The events of a run, in terms of its object O and its sensors, also stored as run
/// attributes. NaN: did not happen.
struct SceneRunSummary {
  std::string object;                 ///< O, the object's name
  double gross_slip_onset_s = 0.0;    ///< O slips on all sensors together: first step of the all-slide run that moves it
  double incipient_onset_s = 0.0;     ///< first partial-slip frame from the release on, before gross slip
  double incipient_lead_s = 0.0;      ///< gross_slip_onset_s - incipient_onset_s
  double pre_slip_fraction = 0.0;     ///< pins in contact at the release that slid before gross slip
  double object_fall_s = 0.0;         ///< O lost: it dropped labels.fall_threshold_mm relative to the sensor
  double predicted_onset_s = 0.0;     ///< Coulomb: sum(mu_i N_i) + support friction falls below m g
  double coulomb_early_s = 0.0;       ///< sum(mu_i N_i) - support friction falls below m g (earliest skin slip)
  double creep_um = 0.0;              ///< O sliding relative to the first sensor's centre pin before the onset
  /// O slips on sensor S: per sensor, the first step from the load on at which every pin of S
  /// in contact slides (NaN: never).
  std::vector<double> slip_on_sensor_s;
  bool held = true;                   ///< O held: not lost during the load, no gross slip before the release
  double sim_time_s = 0.0;            ///< simulated time
  double wall_time_s = 0.0;           ///< wall-clock time of the run
  long long steps = 0;                ///< physics steps
  int mujoco_warnings = 0;            ///< warnings MuJoCo raised (a run with any stops early)
  RunHealth health;                   ///< run health figures and verdict
  std::vector<ControllerAction> actions;             ///< what the run's controller did
  std::map<std::string, double> controller_figures;  ///< what it measured (SceneController::Figures)
};

/// The state of one run, advanced step by step. Construct, Step() until it returns false,
/// then Finish(). Not thread-safe; the scene is shared read-only by many runs.
class SceneRun {
 public:
  /// Prepares this run's copy of `scene`'s model, its sensors (noise streams and pin friction
  /// from `draws`) and its clock. `controller` (which must outlive the run) drives the
  /// actuators along `timeline`.
  SceneRun(const Scene& scene, const SceneRunSettings& settings, const ProtocolTimeline& timeline,
           const RunDraws& draws, SceneController& controller);

  /// Times every step's stages and records the controls into `out` (before the first step).
  void Instrument(RunInstrumentation* out);
  /// Advances one physics step, recording a camera frame into `rec` when one is due;
  /// returns false (without stepping) once the protocol has ended. Throws SimulationError.
  bool Step(RunRecord& rec);
  /// Ends the run: the summary, also written into `rec`'s attributes.
  SceneRunSummary Finish(RunRecord& rec);
  /// Step() until the end, then Finish(); throws SimulationError, or Interrupted when
  /// `*stop` becomes true.
  SceneRunSummary Execute(RunRecord& rec, const std::atomic<bool>* stop);

  /// Simulated time (s), the simulation and the sensors (for viewers and controllers).
  double time() const { return sim_->time(); }
  const Simulation& simulation() const { return *sim_; }
  const TactileSensor& sensor(size_t k = 0) const { return channels_[k].sensor; }
  size_t sensor_count() const { return channels_.size(); }

 private:
  void AddChannels();
  void InitRecord(RunRecord& rec);
  void ApplyControls(double t);
  void RecordControls();
  void ReadContacts(double t);
  void UpdateShellDamping();
  void SwitchToSlidingStep();
  void RecordFrame(double t, double tf);
  void CheckPlausible(double t) const;
  void TrackHealth(double t);
  void WriteAttributes(const SceneRunSummary& s, RunRecord& rec) const;

  const Scene& scene_;
  const SceneRunSettings& settings_;
  const ProtocolTimeline timeline_;
  const RunDraws draws_;
  SceneController& controller_;
  CompiledModel model_;          // this run's copy (friction and damping change per run)
  std::vector<SensorChannel> channels_;
  ShellDamping shell_damping_;   // skin.shell_damping = gel: the shell's damper follows the carried mass
  bool friction_switching_ = false;  // some pin's friction changes as it slides
  std::optional<Simulation> sim_;
  StepClock clock_;
  ObjectWatch watch_;            // the object's onsets, prediction, fall and creep
  std::optional<RunRecorder> recorder_;  // from the first step on
  std::vector<double> controls_;         // the last step's controls, in actuator order
  double end_time_ = 0.0;                // the run ends after this time (the give-up time, or after the loss)
  long long steps_ = 0;                  // physics steps taken
  // Per frame, kept to allocate nothing per step: what the controller and the recorder get.
  FrameInput frame_input_;
  std::vector<const SensorReading*> readings_;
  std::vector<double> stuck_;            // each sensor's stuck share of its contacting pins
  RunInstrumentation* instrument_ = nullptr;
  bool started_ = false;
  std::chrono::steady_clock::time_point wall0_;

  // Run health over the pins of all sensors, in sensor order.
  RunHealthMonitor health_;
  std::vector<float> health_px_;              // all sensors' noise-free pin positions of a frame
  std::vector<std::uint8_t> health_contact_;  // and their contact labels
  bool slipped_since_frame_ = false;          // some pin slipped at a step since the last frame
  double prev_frame_press_ = 0.0;             // the first sensor's commanded pressing position at the last frame
  double prev_frame_rel_z_ = 0.0;             // the object's height relative to the first sensor at the last frame
  bool have_prev_frame_ = false;
};

}  // namespace tactip
