#pragma once
// One run of the rail protocol, step by step: drive the arm, step the physics, read the
// contacts, switch friction, find the onsets, and record a camera frame at each frame time.
// Internal to the rail scenario.

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <limits>
#include <vector>

#include "models/rail_rig.h"
#include "scenarios/rail/rail_config.h"
#include "scenarios/rail/rail_controller.h"
#include "scenarios/rail/rail_scenario.h"
#include "scenarios/rail/rail_schedule.h"
#include "scenarios/rail/run_health.h"
#include "scenarios/rail/shell_damping.h"
#include "scenarios/rail/state_limits.h"
#include "sensors/camera.h"
#include "sensors/dataset.h"
#include "sensors/friction_law.h"
#include "sensors/image_pipeline.h"
#include "sensors/run_recorder.h"
#include "sensors/tactile_sensor.h"
#include "sensors/labels.h"
#include "sim/base/random.h"
#include "sim/simulation.h"

namespace tactip {

/// The compiled rail scene and the element ids a run needs.
struct RailSceneIds {
  BuiltScene scene;
  std::optional<CompiledModel> model;
  int servo_x = -1, servo_z = -1, slider_body = -1, stimulus_geom = -1;
  int slide_dof = -1, arm_z_dof = -1;
  std::vector<TactileSensorIds> sensors;       ///< each TacTip's elements, in the config's order
  std::vector<TactileSensorSpec> sensor_specs;  ///< their cameras, noise and labelling

  /// Compiles the scene of `cfg` (with the parts `options` puts back) and looks its elements
  /// up; throws ModelError.
  RailSceneIds(const RailScenarioConfig& cfg, const SceneOptions& options);
};

/// The state of one run, advanced step by step: each Step() drives the arm with the
/// controller's targets, steps the physics, reads the contacts, switches friction, finds
/// the onsets and, at each camera frame, has every sensor capture a frame, shows them to
/// the controller and records them. Construct, Step() until it returns false, then Finish().
/// The object is held by all sensors together: gross slip is every contacting pin of every
/// sensor sliding, incipient slip some but not all of them; creep is measured on the first
/// sensor's centre pin.
class RailRun {
 public:
  /// Draws the run's variations (depth, friction, noise streams) from (seed, index) and
  /// prepares its own copy of the model. `controller` drives the arm (null: the offline
  /// protocol's schedule); it must outlive the run.
  RailRun(const RailScenarioConfig& cfg, const RailSceneIds& ids, int index, std::uint64_t seed,
          RailController* controller = nullptr);

  /// Drives the arm with `controller` instead (before the first step; it must outlive the run).
  void SetController(RailController* controller) {
    controller_ = controller ? controller : &schedule_controller_;
    end_time_ = controller_->GiveUpTime(sched_);
    limits_ = StateLimits::For(c_, im_.scene.n_collidable, controller_->ExtraPressM());
  }
  /// Times every step's stages and records the controls into `out` (before the first step).
  void Instrument(RunInstrumentation* out);
  /// Advances one physics step, recording a camera frame into `rec` when one is due;
  /// returns false (without stepping) once the protocol has ended. Throws SimulationError.
  bool Step(RunRecord& rec);
  /// Ends the run: the summary, also written into `rec`'s attributes.
  RailRunSummary Finish(RunRecord& rec);
  /// The whole protocol: Step() until the end, then Finish(); throws SimulationError, or
  /// Interrupted when `*stop` becomes true.
  RailRunSummary Execute(RunRecord& rec, const std::atomic<bool>* stop);

  /// Simulated time (s), the simulation and the sensors (for viewers and controllers).
  double time() const { return sim_->time(); }
  const Simulation& simulation() const { return *sim_; }
  /// The first sensor; sensor k of sensor_count().
  const TactileSensor& sensor(size_t k = 0) const { return channels_[k].sensor; }
  size_t sensor_count() const { return channels_.size(); }
  /// The protocol's timeline for this run's press depth.
  const RailSchedule& schedule() const { return sched_; }

 private:
  // This run's draws: press depth and friction coefficient, each on its own stream.
  struct Draws {
    std::uint64_t run_seed;
    double depth_m, mu;
  };
  static Draws Draw(const RailScenarioConfig& cfg, std::uint64_t run_seed);
  RailRun(const RailScenarioConfig& cfg, const RailSceneIds& ids, int index, const Draws& draws,
          RailController* controller);

  // One tactile sensor of the run: what it sees, its pins' friction, its pins' history.
  struct Channel {
    TactileSensor sensor;
    FrictionLaw friction;
    std::vector<double> first_slip_frame_s;        // per pin in contact at the retraction: its first frame
                                                   // labelled slipping, from the retraction to the onset's confirmation
    std::vector<std::uint8_t> contact_at_retract;  // per pin: in contact when the retraction started
    std::vector<double> first_slip_s;              // per pin: first step labelled slipping, retraction to onset
    std::optional<SensorImagePipeline> imaging;    // rendered frames and blob tracking (images.enabled)
  };
  void AddChannels(const RailScenarioConfig& cfg, const Draws& draws);
  void InitRecord(RunRecord& rec);
  void ReadLabels();
  void UpdateShellDamping();  // the gel shell's damper from each sensor's stuck contacts
  void ReadContacts();
  void TrackOnset(double t, bool seek_onset);
  /// From the next step on: SimConfig::SlidingTimestep (a whole fraction of the step), if
  /// smaller than the step (once per run).
  void SwitchToSlidingStep();
  double StepTime(long long n) const;  // the time at which step n starts (after n steps)
  long long NextFrameStep() const;     // the step nearest frame frame_'s time, not before step_
  void TrackPrediction(double t);
  void RecordFrame(double t, double tf);
  void TrackIncipient(double t);
  void TrackFirstSlips(double t);  // each pin's first slipping step from the retraction to the onset
  void TrackEvents(double t, double tf);
  void TrackHealth(double t);
  /// The object's height along the rail relative to the first sensor, m.
  double ObjectHeightOverSensorM() const;
  void CheckPlausible(double t) const;
  void RecordControls();

  const RailScenarioConfig& c_;
  const RailSceneIds& im_;
  const int index_;             // run number
  const int n_;                 // pins of each sensor
  const double depth_m_, mu_;   // this run's press depth and static friction
  CompiledModel model_;         // this run's copy (friction changes per pin)
  std::vector<Channel> channels_;
  ShellDamping shell_damping_;  // skin.shell_damping = gel: the shell's damper follows the carried mass
  bool friction_switching_ = false;  // some pin's friction changes as it slides
  std::optional<Simulation> sim_;
  const RailSchedule sched_;
  ScheduleController schedule_controller_;
  RailController* controller_;  // schedule_controller_ unless given
  std::optional<RunRecorder> recorder_;  // from the first step on
  ArmTargets arm_;              // the targets of the last step
  double dt_;                   // the physics step in force: sim.timestep_s, then the sliding step
  const double weight_N_;

  // Step and frame counters; a step's time counts from the switch to the sliding step.
  long long step_ = 0, frame_ = 0, next_frame_step_ = 0;
  long long switch_step_ = 0;  // the first step at the sliding step (0 before the switch)
  double switch_time_ = 0.0;   // the time at which it starts
  bool sliding_step_ = false;  // the sliding step is in force
  bool started_ = false;

  // Per step: the holding force, the gross-slip label, the pins of all sensors in contact and slipping.
  double holding_N_ = 0.0;  // what the contacts can hold along the rail: sum of mu_s,i N_i + N_i n_i.up
  std::uint8_t gross_ = 0;
  bool all_slide_ = false;                      // every contacting pin of every sensor slides
  double all_slide_since_ = std::nan("");       // first step of the current uninterrupted all_slide_ run
  long long all_slide_frame_ = 0;               // the first frame recorded at or after that step
  int n_contact_ = 0, n_slip_ = 0;
  bool slipped_since_frame_ = false;  // some pin slipped at a step since the last frame
  double prev_frame_x_ = std::numeric_limits<double>::quiet_NaN();  // the arm's commanded normal position at the last frame
  double prev_frame_rel_z_ = 0.0;  // the object's height relative to the first sensor at the last frame

  // Per frame: is the state physically possible (StateLimits)?
  StateLimits limits_;  // for the controller in charge

  RunInstrumentation* instrument_ = nullptr;

  // Run events and health.
  RailRunSummary sum_;
  RunHealthMonitor health_;     // over the pins of all sensors, in sensor order
  std::vector<float> health_px_;                 // all sensors' noise-free pin positions of a frame
  std::vector<std::uint8_t> health_contact_;     // and their contact labels
  bool retract_seen_ = false;   // contact_at_retract is set
  double end_time_ = 0.0;
  double prev_margin_, prev_skin_, prev_t_ = 0.0;
  double rel_ref_, lift_rel_ref_, creep_ref_, creep_max_ = 0.0;
  bool ending_ = false, left_behind_ = false;
  std::chrono::steady_clock::time_point wall0_;
};

}  // namespace tactip
