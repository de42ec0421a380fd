// A sliding object keeps its contacts: during gross slip on the rail, the normal forces
// stay what the press gives (Coulomb friction does not change them) once fast-sliding
// contacts lose MuJoCo's velocity target on their friction rows
// (sim.free_sliding_speed_mm_s, sim/friction_reference.h); with the target they chatter.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "models/skin.h"
#include "mujoco_warning_guard.h"
#include "scenarios/rail/rail.h"

namespace tactip {
namespace {

class SlidingContactTest : public testing::MujocoWarningGuard {};

struct SlideForces {
  double onset_N = 0.0;    ///< total normal force at the frame before the onset
  double min_ratio = 0.0;  ///< smallest total normal force while sliding / onset_N
  int onset_pins = 0;      ///< pins in contact at the frame before the onset
  int min_pins = 0;        ///< fewest pins in contact while sliding
  int sliding_frames = 0;  ///< frames examined
};

// Deterministic rail run, frames at 500 Hz; the sliding window runs from `skip_frames`
// frames after the onset (by default 10 ms, past the release) to halfway to the first frame
// without contact (before the plate's edge reaches the contact patch).
SlideForces Slide(double free_sliding_speed_mm_s, RailScenarioConfig c = {}, double retract_speed_mm_s = 1.0,
                  size_t skip_frames = 5) {
  c.contact.friction_jitter = 0.0;
  c.rail.press_depth_jitter_mm = 0.0;
  c.rail.retract_speed_mm_s = retract_speed_mm_s;
  c.sensor.pixel_noise_px = 0.0;
  c.sensor.noise_model = "independent";
  c.sensor.dropout_prob = 0.0;
  c.sensor.frame_rate_hz = 500.0;
  c.sim.free_sliding_speed_mm_s = free_sliding_speed_mm_s;
  const RailScenario scenario(c);
  RunRecord rec;
  const RailRunSummary s = scenario.Run(0, 1, rec);
  SlideForces out;
  if (std::isnan(s.gross_slip_onset_s)) return out;
  const SensorRecord& sensor = rec.sensors[0];
  const size_t T = rec.frames(), N = static_cast<size_t>(sensor.n_pins);
  const auto total = [&](size_t f) {
    double n = 0.0;
    for (size_t i = 0; i < N; ++i) n += sensor.normal_N[f * N + i];
    return n;
  };
  const auto pins = [&](size_t f) {
    int n = 0;
    for (size_t i = 0; i < N; ++i) n += sensor.pin_contact[f * N + i] ? 1 : 0;
    return n;
  };
  const size_t onset = static_cast<size_t>(
      std::lower_bound(rec.time.begin(), rec.time.end(), s.gross_slip_onset_s) - rec.time.begin());
  size_t lost = onset;
  while (lost < T && pins(lost) > 0) ++lost;
  out.onset_N = total(onset - 1);
  out.onset_pins = pins(onset - 1);
  out.min_ratio = 1e9;
  out.min_pins = out.onset_pins;
  for (size_t f = onset + skip_frames; f < (onset + lost) / 2; ++f) {
    out.min_ratio = std::min(out.min_ratio, total(f) / out.onset_N);
    out.min_pins = std::min(out.min_pins, pins(f));
    ++out.sliding_frames;
  }
  return out;
}

TEST_F(SlidingContactTest, FastSlidingContactsKeepTheirNormalForces) {
  const SlideForces now = Slide(30.0);
  ASSERT_GE(now.sliding_frames, 10);
  EXPECT_GT(now.onset_N, 0.5);
  // Measured: 0.79-0.97 of the onset force, all 19 pins in contact.
  EXPECT_GT(now.min_ratio, 0.7) << "over " << now.sliding_frames << " frames";
  EXPECT_EQ(now.min_pins, now.onset_pins);
}

TEST_F(SlidingContactTest, WithMujocosFrictionTargetTheSlidingContactsChatter) {
  // The defect the setting removes (measured at 2 ms throughout: total normal force down to
  // 0.02 N, 1 of 19 pins in contact), which the check above catches.
  RailScenarioConfig c;
  c.sim.sliding_timestep_s = 0.0;
  const SlideForces old = Slide(0.0, c);
  ASSERT_GE(old.sliding_frames, 10);
  EXPECT_LT(old.min_ratio, 0.5);
  EXPECT_LT(old.min_pins, old.onset_pins / 2);
}

// The shell skin's gel damper (ratio 0.08): the released shell rings while the object slides.
// At the light shell's validated step the sliding contacts keep their normal forces; sliding
// at 2 ms (refused by the config's rules) they chatter, the reason for kLightShellValidatedStepS.
// On the lumped shell (gel shear modulus E_gel / 3): the stiffest shell of the defaults' gel
// rings fastest (40 Hz alone; the default 10 kPa shell 22 Hz).
RailScenarioConfig GelShell(double timestep_s) {
  RailScenarioConfig c;
  c.skin.gel_shear_modulus_kpa = 0.0;
  c.skin.shell_damping = "gel";
  c.sim.timestep_s = timestep_s;
  return c;
}

TEST_F(SlidingContactTest, ARingingGelShellKeepsItsSlidingContactsAtItsValidatedStep) {
  const SlideForces now = Slide(30.0, GelShell(kLightShellValidatedStepS));
  ASSERT_GE(now.sliding_frames, 10);
  // Measured: 0.92 of the onset force, all 19 pins in contact.
  EXPECT_GT(now.min_ratio, 0.7) << "over " << now.sliding_frames << " frames";
  EXPECT_EQ(now.min_pins, now.onset_pins);
}

TEST_F(SlidingContactTest, ARingingGelShellHeldAtTheDefaultStepKeepsItsSlidingContactsOnTheSlidingStep) {
  // 2 ms until the onset, 1 ms from it on (sim.sliding_timestep_s).
  RailScenarioConfig c = GelShell(0.002);
  ASSERT_DOUBLE_EQ(c.sim.SlidingTimestep(), kLightShellValidatedStepS);
  const SlideForces now = Slide(30.0, c);
  ASSERT_GE(now.sliding_frames, 10);
  EXPECT_GT(now.min_ratio, 0.7) << "over " << now.sliding_frames << " frames";
  EXPECT_EQ(now.min_pins, now.onset_pins);
}

TEST_F(SlidingContactTest, ARingingGelShellChattersAtTwiceItsValidatedStep) {
  // Measured: down to 0.04 of the onset force, 6 of 19 pins in contact.
  RailScenarioConfig c = GelShell(2.0 * kLightShellValidatedStepS);
  c.sim.check_stability = false;  // the rule that refuses it
  c.sim.sliding_timestep_s = 0.0;  // and the sliding step that would hide it
  const SlideForces coarse = Slide(30.0, c);
  ASSERT_GE(coarse.sliding_frames, 10);
  EXPECT_LT(coarse.min_ratio, 0.5);
  EXPECT_LT(coarse.min_pins, coarse.onset_pins / 2);
}

// At the hardware's 0.1 mm/s the release itself (the window from the onset on) loses some
// sliding contacts for a step at a 2 ms step; at 1 ms it keeps them all, and so does the
// default, which keeps 2 ms until the onset and steps 1 ms from it on (sim.sliding_timestep_s;
// docs/model.md, 'Sliding contacts').
TEST_F(SlidingContactTest, AtTheHardwaresSpeedTheReleaseKeepsEveryContactAtOneMillisecond) {
  RailScenarioConfig c;
  c.sim.timestep_s = 0.001;
  const SlideForces fine = Slide(30.0, c, 0.1, 0);
  ASSERT_GE(fine.sliding_frames, 20);
  // Measured: 0.985 of the onset force, all 19 pins in contact.
  EXPECT_GT(fine.min_ratio, 0.9) << "over " << fine.sliding_frames << " frames";
  EXPECT_EQ(fine.min_pins, fine.onset_pins);
}

TEST_F(SlidingContactTest, AtTheHardwaresSpeedTheReleaseLosesContactsForAStepAtTwoMilliseconds) {
  // The defect the sliding step removes. Measured: 0.62 of the onset force, 13 of 19 pins in
  // contact, two steps after the onset; from 10 ms after it on, 0.86 and all 19.
  RailScenarioConfig c;
  c.sim.sliding_timestep_s = 0.0;
  const SlideForces coarse = Slide(30.0, c, 0.1, 0);
  ASSERT_GE(coarse.sliding_frames, 20);
  EXPECT_LT(coarse.min_ratio, 0.75);
  EXPECT_LT(coarse.min_pins, coarse.onset_pins);
}

TEST_F(SlidingContactTest, AtTheHardwaresSpeedTheDefaultReleaseKeepsEveryContact) {
  // The same run with the defaults: 2 ms while held, 1 ms from the onset on. Measured: 0.97
  // of the onset force and all 19 pins (1 ms throughout: 0.985 and 19).
  const RailScenarioConfig c;
  ASSERT_EQ(c.sim.timestep_s, 0.002);
  ASSERT_EQ(c.sim.SlidingTimestep(), 0.001);
  const SlideForces now = Slide(30.0, c, 0.1, 0);
  ASSERT_GE(now.sliding_frames, 20);
  EXPECT_GT(now.min_ratio, 0.9) << "over " << now.sliding_frames << " frames";
  EXPECT_EQ(now.min_pins, now.onset_pins);
}

}  // namespace
}  // namespace tactip
