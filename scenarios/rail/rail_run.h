#pragma once
// One run of the rail protocol, step by step: drive the arm, step the physics, read the
// contacts, switch friction, find the onsets, and record a camera frame at each frame time.
// Internal to the rail scenario.

#include <atomic>
#include <cstdint>
#include <optional>
#include <string>
#include <limits>
#include <vector>

#include "models/rail_rig.h"
#include "scenarios/rail/rail_config.h"
#include "scenarios/rail/rail_scenario.h"
#include "scenarios/rail/rail_schedule.h"
#include "scenarios/rail/run_health.h"
#include "scenarios/rail/state_limits.h"
#include "sensors/camera.h"
#include "sensors/dataset.h"
#include "sensors/labels.h"
#include "sim/base/random.h"
#include "sim/simulation.h"

namespace tactip {

/// The compiled rail scene and the element ids a run needs.
struct RailSceneIds {
  BuiltScene scene;
  std::optional<CompiledModel> model;
  int servo_x = -1, servo_z = -1, sensor_body = -1, slider_body = -1, stimulus_geom = -1;
  int slide_dof = -1, arm_z_dof = -1;
  std::vector<int> pin_site, pin_outer_site, pin_geom;  ///< per pin; -1: no outer site / no contact geom
  std::vector<int> slot_of_geom;                         ///< geom id -> pin index (or -1)
  double marker_rock_m_N = 0.0;  ///< inner marker moves by -this * tangential contact force (ridge pivot)
  double apex_x_m = 0.0;         ///< dome apex in the sensor frame

  /// Compiles the scene of `cfg` (with the parts `options` puts back) and looks its elements
  /// up; throws ModelError.
  RailSceneIds(const RailScenarioConfig& cfg, const SceneOptions& options);
};

/// The state of one run. Construct, then Execute() once.
class RailRun {
 public:
  /// Draws the run's variations (depth, friction, noise streams) from (seed, index) and
  /// prepares its own copy of the model.
  RailRun(const RailScenarioConfig& cfg, const RailSceneIds& ids, int index, std::uint64_t seed);

  /// Times every step's stages and records the controls into `out` (before Execute).
  void Instrument(RunInstrumentation* out);
  /// Simulates the whole protocol into `rec`; throws SimulationError or Interrupted.
  RailRunSummary Execute(RunRecord& rec, const std::atomic<bool>* stop);

 private:
  // This run's draws: press depth and friction coefficient, each on its own stream.
  struct Draws {
    std::uint64_t run_seed;
    double depth_m, mu;
  };
  static Draws Draw(const RailScenarioConfig& cfg, std::uint64_t run_seed);
  RailRun(const RailScenarioConfig& cfg, const RailSceneIds& ids, int index, const Draws& draws);

  void SetUpFriction(std::uint64_t run_seed);
  void InitRecord(RunRecord& rec, int index) const;
  void ReadContactsAndLabel();
  void UpdateFriction();
  void TrackOnset(double t, bool seek_onset);
  void TrackPrediction(double t);
  void RecordFrame(double t, RunRecord& rec);
  void RecordPins(RunRecord& rec);
  void RecordExternal(RunRecord& rec);
  void RecordContacts(double t, RunRecord& rec);
  void TrackEvents(double t, double tf);
  void TrackHealth(double t);
  void CheckPlausible(double t) const;
  void RecordControls(double t);
  void Finish(RunRecord& rec);

  const RailScenarioConfig& c_;
  const RailSceneIds& im_;
  const int index_;             // run number
  const int n_;                 // pins
  const double depth_m_, mu_;   // this run's press depth and static friction
  DetectionNoise noise_, ext_noise_;
  CompiledModel model_;         // this run's copy (friction changes per pin)
  std::vector<double> mu_pin_;  // per pin: static coefficient
  std::vector<double> mu_cur_;  // per pin: coefficient in force
  std::vector<std::uint8_t> sliding_;  // per pin: kinetic friction in force
  std::optional<Simulation> sim_;
  const RailSchedule sched_;
  const double dt_, weight_N_;
  PinholeCamera camera_;
  const ExternalCamera ext_camera_;

  // Per step: contacts, labels and the holding force.
  std::vector<GeomContact> contacts_;
  std::vector<std::array<double, 3>> tangential_;
  std::vector<PinContactSample> samples_;
  std::vector<std::uint8_t> pin_contact_, pin_slip_;
  FrameLabels labels_;
  double holding_N_ = 0.0;  // what the contacts can hold along the rail: sum of mu_s,i N_i + N_i n_i.up
  std::uint8_t gross_ = 0;

  // Per frame: image positions and detections.
  std::vector<float> px_, prev_px_, ext_px_, prev_ext_px_;
  std::vector<float> clean_px_;  // this frame's pin image positions before camera noise
  double image_gain_px_m_ = 0.0; // this frame's largest image motion per metre of pin motion
  bool slipped_since_frame_ = false;  // some pin slipped at a step since the last frame
  double prev_frame_x_ = std::numeric_limits<double>::quiet_NaN();  // the arm's commanded normal position at the last frame
  std::vector<std::uint8_t> valid_, ext_valid_;
  std::array<double, 3> origin_{};
  std::array<double, 9> rot_{};

  // Per frame: is the state physically possible (StateLimits)?
  const StateLimits limits_;
  std::vector<std::array<double, 3>> rest_marker_m_;  // per pin: its marker at rest, sensor frame
  std::vector<double> marker_shift_m_, normal_N_;      // per pin, this frame

  RunInstrumentation* instrument_ = nullptr;

  // Run events and health.
  RailRunSummary sum_;
  RunHealthMonitor health_;
  std::vector<std::uint8_t> slid_before_gross_, contact_at_retract_;
  double end_time_ = 0.0;
  double prev_margin_, prev_skin_, prev_t_ = 0.0;
  double rel_ref_, lift_rel_ref_, creep_ref_, creep_max_ = 0.0;
  bool ending_ = false, left_behind_ = false;
};

}  // namespace tactip
