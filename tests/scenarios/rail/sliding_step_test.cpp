// The sliding step (sim.sliding_timestep_s): a rail run keeps sim.timestep_s until the
// gross-slip onset (the first step in which every contacting pin slides) and takes the finer
// step from it on. Everything before the onset is the run without it, frame for frame; the
// run's clock stays MuJoCo's; the config refuses a step too small to run.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "mujoco_warning_guard.h"
#include "scenarios/rail/rail.h"
#include "scenarios/rail/rail_run.h"
#include "scenarios/rail/rail_schedule.h"
#include "sim/base/errors.h"

namespace tactip {
namespace {

class SlidingStepTest : public testing::MujocoWarningGuard {};

struct SteppedRun {
  RailRunSummary summary;
  RunRecord record;
};

// A deterministic run at 1 mm/s, noise off.
RailScenarioConfig Deterministic(double sliding_timestep_s) {
  RailScenarioConfig c;
  c.contact.friction_jitter = 0.0;
  c.rail.press_depth_jitter_mm = 0.0;
  c.rail.retract_speed_mm_s = 1.0;
  c.sensor.pixel_noise_px = 0.0;
  c.sensor.noise_model = "independent";
  c.sensor.dropout_prob = 0.0;
  c.sim.sliding_timestep_s = sliding_timestep_s;
  return c;
}

SteppedRun Simulate(double sliding_timestep_s) {
  const RailScenario scenario(Deterministic(sliding_timestep_s));
  SteppedRun out;
  out.summary = scenario.Run(0, 1, out.record);
  return out;
}

// Equal, or both NaN.
void ExpectSame(double a, double b, const char* what) {
  if (std::isnan(a) && std::isnan(b)) return;
  EXPECT_EQ(a, b) << what;
}

TEST_F(SlidingStepTest, BeforeTheOnsetTheRunIsTheOneWithoutIt) {
  const SteppedRun coarse = Simulate(0.0), refined = Simulate(0.001);
  ASSERT_FALSE(std::isnan(coarse.summary.gross_slip_onset_s));
  EXPECT_EQ(refined.summary.gross_slip_onset_s, coarse.summary.gross_slip_onset_s);
  const std::vector<double>& t = coarse.record.time;
  const size_t onset = static_cast<size_t>(
      std::lower_bound(t.begin(), t.end(), coarse.summary.gross_slip_onset_s) - t.begin());
  ASSERT_GT(onset, 100u);
  ASSERT_GT(refined.record.frames(), onset + 10);
  const SensorRecord &a = coarse.record.sensors[0], &b = refined.record.sensors[0];
  const size_t n = static_cast<size_t>(a.n_pins);
  // Every frame up to the onset frame (the first at or after it) is the same, bit for bit.
  for (size_t f = 0; f < onset; ++f) {
    for (size_t k = 0; k < 2 * n; ++k) ASSERT_EQ(b.pos_px[2 * n * f + k], a.pos_px[2 * n * f + k]) << "frame " << f;
    for (size_t i = 0; i < n; ++i) ASSERT_EQ(b.normal_N[n * f + i], a.normal_N[n * f + i]) << "frame " << f;
  }
  // And what the run measures while held.
  const RailRunSummary &x = coarse.summary, &y = refined.summary;
  ExpectSame(y.incipient_onset_s, x.incipient_onset_s, "incipient onset");
  ExpectSame(y.pre_slip_fraction, x.pre_slip_fraction, "pre-slip fraction");
  EXPECT_EQ(y.creep_um, x.creep_um);
  EXPECT_EQ(y.health.flicker_max, x.health.flicker_max);
  EXPECT_EQ(y.health.pin_speed_px, x.health.pin_speed_px);
  EXPECT_EQ(y.health.stick_creep_um, x.health.stick_creep_um);
  EXPECT_EQ(y.health.energy_gain, x.health.energy_gain);
  EXPECT_EQ(y.health.ok, x.health.ok);
  // After it the run takes more, finer steps: 1 ms against 2 ms from the onset to the end.
  EXPECT_GT(y.steps, x.steps);
}

TEST_F(SlidingStepTest, TheRunsClockIsMujocos) {
  // The time the run gives its steps (frames, controller, end) is MuJoCo's: the step taken
  // when the switch comes still counts at the configured step.
  const RailScenarioConfig c = Deterministic(0.001);
  const RailScene ids(c, SceneOptions{});
  RailRun run(c, ids, 0, 1);
  RunRecord rec;
  const RailRunSummary s = run.Execute(rec, nullptr);
  ASSERT_FALSE(std::isnan(s.gross_slip_onset_s));
  EXPECT_NEAR(s.sim_time_s, run.time(), 1e-9);
  // The run's frames are the camera's: one per 10 ms, the last within a frame of the end.
  EXPECT_NEAR(rec.time.back(), 0.01 * static_cast<double>(rec.frames() - 1), 1e-9);
  EXPECT_LE(s.sim_time_s - rec.time.back(), 0.01 + 1e-9);
}

TEST_F(SlidingStepTest, TheSlidingStepIsTheLargestWholeFractionOfTheStepWithinItAndZeroKeepsTheStep) {
  RailScenarioConfig c;
  c.sim.timestep_s = 0.0005;
  c.sim.sliding_timestep_s = 0.001;
  EXPECT_EQ(c.sim.SlidingTimestep(), 0.0005);  // not smaller: the step itself
  c.sim.sliding_timestep_s = 0.0;
  EXPECT_EQ(c.sim.SlidingTimestep(), 0.0005);
  c.sim.timestep_s = 0.002;
  c.sim.sliding_timestep_s = 0.001;
  EXPECT_EQ(c.sim.SlidingTimestep(), 0.001);  // the default: exactly half
  c.sim.timestep_s = 0.0015;
  EXPECT_DOUBLE_EQ(c.sim.SlidingTimestep(), 0.00075);  // 1.5 ms / 2, not 1 ms
  c.sim.timestep_s = 0.003;
  EXPECT_DOUBLE_EQ(c.sim.SlidingTimestep(), 0.001);  // 3 ms / 3
  c.sim.sliding_timestep_s = 0.0009;
  EXPECT_DOUBLE_EQ(c.sim.SlidingTimestep(), 0.00075);  // 3 ms / 4
  c.sim.timestep_s = 0.006;
  c.sim.sliding_timestep_s = 0.0012;  // the ratio rounds to just above 5: still 6 ms / 5
  EXPECT_DOUBLE_EQ(c.sim.SlidingTimestep(), 0.0012);
}

// Follows the schedule and measures, at each frame, how far the step it was taken at lies
// from the camera's frame time.
class FrameGridController : public RailController {
 public:
  explicit FrameGridController(const RailSchedule& s) : schedule_(s) {}
  ArmTargets Targets(double t) override {
    step_time_s_ = t;
    return {schedule_.X(t), schedule_.Z(t)};
  }
  void OnFrame(const FrameInput& in) override {
    largest_offset_s = std::max(largest_offset_s, std::abs(step_time_s_ - in.time_s));
    last_frame_s = in.time_s;
  }
  double largest_offset_s = 0.0, last_frame_s = 0.0;

 private:
  RailSchedule schedule_;
  double step_time_s_ = 0.0;
};

TEST_F(SlidingStepTest, FramesStayOnTheCamerasGridAfterTheSwitch) {
  // A 30 Hz camera on a step of 1/510 s (17 steps a frame): 1 ms does not divide the frame
  // period, so the sliding step is half the step and the frames stay on the steps' grid.
  RailScenarioConfig c = Deterministic(0.001);
  c.sensor.frame_rate_hz = 30.0;
  c.sim.timestep_s = 1.0 / 510.0;
  ASSERT_DOUBLE_EQ(c.sim.SlidingTimestep(), 1.0 / 1020.0);
  const RailScene ids(c, SceneOptions{});
  FrameGridController controller(RailSchedule(c.rail, c.rail.press_depth_mm * 1e-3, c.rail.retract_speed_mm_s));
  RailRun run(c, ids, 0, 1, controller);
  RunRecord rec;
  const RailRunSummary s = run.Execute(rec, nullptr);
  ASSERT_FALSE(std::isnan(s.gross_slip_onset_s));
  ASSERT_GT(controller.last_frame_s, s.gross_slip_onset_s + 0.1);  // frames well after the switch
  EXPECT_LT(controller.largest_offset_s, 1e-9);
}

TEST_F(SlidingStepTest, AStepTooSmallToRunIsRefused) {
  RailScenarioConfig c;
  c.sim.sliding_timestep_s = 1e-7;
  try {
    c.ValidateRules();
    FAIL() << "accepted sim.sliding_timestep_s = 1e-7";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("sim.sliding_timestep_s"), std::string::npos) << e.what();
  }
  // Allowed on its own, but the whole fraction of a 15 us step within it would be 7.5 us.
  c.sim.timestep_s = 1.5e-5;
  c.sim.sliding_timestep_s = 1e-5;
  ASSERT_LT(c.sim.SlidingTimestep(), SimConfig::kMinTimestepS);
  try {
    c.sim.ValidateRules();
    FAIL() << "accepted a sliding step of " << c.sim.SlidingTimestep() << " s";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("below 0.00001 s"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace tactip
