// The sliding step (sim.sliding_timestep_s): a rail run keeps sim.timestep_s until the
// gross-slip onset and takes the finer step from it on. Everything before the onset is the
// run without it, frame for frame; the frames keep their times; the config refuses a step
// too small to run.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "mujoco_warning_guard.h"
#include "scenarios/rail.h"
#include "sim/base/errors.h"

namespace tactip {
namespace {

class SlidingStepTest : public testing::MujocoWarningGuard {};

struct SteppedRun {
  RailRunSummary summary;
  RunRecord record;
};

// A short deterministic run at 1 mm/s, noise off.
SteppedRun Simulate(double sliding_timestep_s) {
  RailScenarioConfig c;
  c.contact.friction_jitter = 0.0;
  c.rail.press_depth_jitter_mm = 0.0;
  c.rail.retract_speed_mm_s = 1.0;
  c.sensor.pixel_noise_px = 0.0;
  c.sensor.dropout_prob = 0.0;
  c.sim.sliding_timestep_s = sliding_timestep_s;
  const RailScenario scenario(c);
  SteppedRun out;
  out.summary = scenario.Run(0, 1, out.record);
  return out;
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
    ASSERT_EQ(refined.record.time[f], t[f]) << "frame " << f;
    for (size_t k = 0; k < 2 * n; ++k) ASSERT_EQ(b.pos_px[2 * n * f + k], a.pos_px[2 * n * f + k]) << "frame " << f;
    for (size_t i = 0; i < n; ++i) ASSERT_EQ(b.normal_N[n * f + i], a.normal_N[n * f + i]) << "frame " << f;
  }
  // After it the frames keep the camera's times, and the run took more (finer) steps.
  const size_t common = std::min(coarse.record.frames(), refined.record.frames());
  for (size_t f = onset; f < common; ++f) {
    EXPECT_NEAR(refined.record.time[f], t[f], 1e-12) << "frame " << f;
  }
  EXPECT_GT(refined.summary.steps, coarse.summary.steps);
  // The simulated time counts both steps: it ends within a frame after the last frame.
  EXPECT_GE(refined.summary.sim_time_s, refined.record.time.back());
  EXPECT_LE(refined.summary.sim_time_s - refined.record.time.back(), 0.01 + 1e-9);
}

TEST_F(SlidingStepTest, ALargerSlidingStepThanTheStepChangesNothing) {
  RailScenarioConfig c;
  c.sim.timestep_s = 0.0005;
  c.sim.sliding_timestep_s = 0.001;
  EXPECT_EQ(c.sim.SlidingTimestep(), 0.0005);
  c.sim.sliding_timestep_s = 0.0;
  EXPECT_EQ(c.sim.SlidingTimestep(), 0.0005);
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
}

}  // namespace
}  // namespace tactip
