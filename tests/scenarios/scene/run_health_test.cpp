// Run health: the monitor's figures on frames whose answer is known, the acceptance of the
// rail scene on every stimulus (no chatter, creep or slip before the onset), and that a
// chattering configuration is flagged rather than written as good data.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <ostream>
#include <string>
#include <vector>

#include "scenarios/rail/rail.h"
#include "scenarios/scene/run_health.h"

namespace tactip {
namespace {

constexpr double kHealthCreepLimitUm = 20.0;       // acceptance: creep before the onset
constexpr double kQuasiStaticSpeedPx = 0.1;  // a held pin moves far less than the noise (0.5 px/frame); chatter moved 1-3

TEST(RunHealthMonitorTest, CountsTransitionsSpeedAndCreepWhileHeld) {
  HealthConfig cfg;
  RunHealthMonitor m(2, cfg);
  std::vector<float> px = {0, 0, 10, 10};
  std::vector<std::uint8_t> contact = {1, 1};
  m.Frame(false, false, px.data(), contact.data(), false, std::nan(""));  // not held: ignored
  m.Frame(true, true, px.data(), contact.data(), false, 1e-6);
  // Pin 1 leaves and returns three times; pin 0 moves 0.3 px.
  for (int k = 0; k < 3; ++k) {
    contact[1] = 0;
    m.Frame(true, true, px.data(), contact.data(), false, 6e-6);
    contact[1] = 1;
    m.Frame(true, true, px.data(), contact.data(), false, 11e-6);
  }
  px[0] = 0.3f;
  m.Frame(true, true, px.data(), contact.data(), false, 31e-6);
  // After a pin slips, speed and creep are no longer judged.
  px[0] = 5.0f;
  m.Frame(true, true, px.data(), contact.data(), true, 1.0);
  const RunHealth h = m.Result();
  EXPECT_EQ(h.flicker_max, 6);
  EXPECT_EQ(h.flicker_pin, 1);
  EXPECT_NEAR(h.pin_speed_px, 0.3, 1e-6);
  EXPECT_NEAR(h.stick_creep_um, 30.0, 1e-6);
  EXPECT_FALSE(h.ok);
  EXPECT_NE(h.reason.find("pin 1 flickered in and out of contact 6 times"), std::string::npos) << h.reason;
  EXPECT_NE(h.reason.find("pins moved 0.3 px/frame"), std::string::npos) << h.reason;
  EXPECT_NE(h.reason.find("crept 30 um"), std::string::npos) << h.reason;
}

TEST(RunHealthMonitorTest, PinMotionTheSensorsOwnMotionExplainsIsNotCounted) {
  HealthConfig cfg;
  RunHealthMonitor m(1, cfg);
  std::vector<float> px = {0, 0};
  std::vector<std::uint8_t> contact = {1};
  m.Frame(true, true, px.data(), contact.data(), false, 0.0);
  // The retraction explains up to 1.5 px this frame: a 1.6 px move is 0.1 px beyond it.
  px[0] = 1.6f;
  m.Frame(true, true, px.data(), contact.data(), false, 0.0, 1.5);
  EXPECT_NEAR(m.Result().pin_speed_px, 0.1, 1e-6);
  EXPECT_TRUE(m.Result().ok) << m.Result().reason;
  // The same move with the sensor still is 1.6 px of unexplained motion.
  px[0] = 3.2f;
  m.Frame(true, true, px.data(), contact.data(), false, 0.0, 0.0);
  EXPECT_NEAR(m.Result().pin_speed_px, 1.6, 1e-6);
  EXPECT_NE(m.Result().reason.find("more than the sensor's motion explains"), std::string::npos);
}

TEST(RunHealthMonitorTest, EnergyCreatedIsJudgedAgainstTheStoredEnergy) {
  HealthConfig cfg;
  RunHealthMonitor m(1, cfg);
  m.Step(-1.0, 2.0);  // dissipation is never counted
  m.Step(1e-3, 2.0);
  EXPECT_NEAR(m.Result().energy_gain, 5e-4, 1e-12);
  EXPECT_TRUE(m.Result().ok);
  m.Step(0.04, 2.0);  // 0.0205 x the stored energy: over health.max_energy_gain = 0.02
  EXPECT_FALSE(m.Result().ok);
  EXPECT_NE(m.Result().reason.find("health.max_energy_gain"), std::string::npos);
}

struct HealthScene {
  const char* stimulus;
  double mass_kg, depth_mm;
};
void PrintTo(const HealthScene& s, std::ostream* os) {
  *os << s.stimulus << ", " << s.mass_kg << " kg, " << s.depth_mm << " mm";
}

// Deterministic, noise-free runs of the default rail scene.
RailScenarioConfig Quiet(const HealthScene& s) {
  RailScenarioConfig c;
  c.rail.stimulus = s.stimulus;
  c.object.mass_kg = s.mass_kg;
  c.rail.press_depth_mm = s.depth_mm;
  c.rail.lift_mm = 20.0;
  c.rail.retract_speed_mm_s = 0.2;
  c.sensor.pixel_noise_px = 0.0;
  c.sensor.noise_model = "independent";
  c.sensor.dropout_prob = 0.0;
  return c;
}

class SceneHealthTest : public ::testing::TestWithParam<HealthScene> {};

TEST_P(SceneHealthTest, HeldObjectNeitherChattersNorCreepsNorSlipsBeforeTheOnset) {
  const RailScenario scenario(Quiet(GetParam()));
  RunRecord rec;
  const RailRunSummary s = scenario.Run(0, 3, rec);
  ASSERT_TRUE(s.held);
  ASSERT_FALSE(std::isnan(s.gross_slip_onset_s));
  EXPECT_TRUE(s.health.ok) << s.health.reason;
  EXPECT_LE(s.health.flicker_max, 2);
  EXPECT_LT(s.health.pin_speed_px, kQuasiStaticSpeedPx);
  EXPECT_LT(s.creep_um, kHealthCreepLimitUm);
  // No pin slips while the object is held, before the frame of the onset.
  const size_t N = static_cast<size_t>(rec.sensors[0].n_pins);
  for (size_t f = 0; f < rec.frames(); ++f) {
    if (rec.time[f] < s.retract_start_s - 0.5 || rec.time[f] >= s.gross_slip_onset_s - 1e-9) continue;
    for (size_t i = 0; i < N; ++i)
      ASSERT_EQ(rec.sensors[0].pin_slip[f * N + i], 0) << "pin " << i << " at " << rec.time[f] << " s";
  }
  // Coulomb: the onset within a frame of sum(mu N) + normal push + rail friction = m g.
  EXPECT_NEAR(s.gross_slip_onset_s, s.predicted_onset_s, 0.01);
}

INSTANTIATE_TEST_SUITE_P(EveryStimulus, SceneHealthTest,
                         ::testing::Values(HealthScene{"flat", 0.05, 3.0}, HealthScene{"curved80", 0.4, 4.5},
                                           HealthScene{"curved40", 0.2, 3.0}, HealthScene{"curved20", 0.1, 3.0}));

TEST(SceneHealthTest, TheSkinLettingGoUnderTheStillObjectIsGrossSlipFromThatStep) {
  // A small skin on the acrylic rig retracted fast (the layout-1 fixture's scene): the skin
  // lets go a step (2 ms) before the object follows - every contacting pin slides, the object
  // not yet moving - and a camera frame falls on that step. It is gross slip: the onset is
  // dated back to it, so no frame before the onset shows a slipping pin and that frame carries
  // the label (before: onset 3.252 s, the frame at 3.250 s all pins slipping, labelled static).
  RailScenarioConfig c;
  c.skin.marker_model = "pins";
  c.skin.gel_shear_modulus_kpa = 0.0;  // the fixture's lumped shell
  c.sim.free_sliding_speed_mm_s = 0.0;
  c.rail.stimulus = "acrylic";
  c.skin.rings = 2;
  c.sensor.frame_rate_hz = 20.0;
  c.rail.lift_mm = 5.0;
  c.rail.hold_s = 0.1;
  c.rail.settle_s = 0.1;
  c.rail.retract_speed_mm_s = 5.0;
  c.rail.post_fall_s = 0.1;
  RunRecord rec;
  const RailRunSummary s = RailScenario(c).Run(0, 5, rec);
  ASSERT_FALSE(std::isnan(s.gross_slip_onset_s));
  EXPECT_NEAR(s.gross_slip_onset_s, 3.250, 1e-6);
  const SensorRecord& sensor = rec.sensors[0];
  const size_t N = static_cast<size_t>(sensor.n_pins);
  const size_t onset_frame = static_cast<size_t>(
      std::lower_bound(rec.time.begin(), rec.time.end(), s.gross_slip_onset_s - 1e-9) - rec.time.begin());
  ASSERT_LT(onset_frame, rec.frames());
  EXPECT_NEAR(rec.time[onset_frame], s.gross_slip_onset_s, 1e-9);  // a frame on the onset's step
  EXPECT_EQ(sensor.gross_slip[onset_frame], 1);
  for (size_t f = 0; f < onset_frame; ++f) {
    EXPECT_EQ(sensor.gross_slip[f], 0) << rec.time[f];
    if (rec.time[f] < s.retract_start_s) continue;
    for (size_t i = 0; i < N; ++i) ASSERT_EQ(sensor.pin_slip[f * N + i], 0) << "pin " << i << " at " << rec.time[f];
  }
}

TEST(SceneHealthTest, ChatteringContactsAreFlaggedNotWrittenAsGoodData) {
  // MuJoCo's own noslip with a hard touch-down (the stability check off, or it is refused).
  RailScenarioConfig c = Quiet(HealthScene{"curved40", 0.1, 3.0});
  c.sim.noslip = "mujoco";
  c.contact.impedance_min = 0.99;
  c.sim.check_stability = false;
  const RailScenario scenario(c);
  RunRecord rec;
  const RailRunSummary s = scenario.Run(0, 3, rec);
  EXPECT_FALSE(s.health.ok);
  EXPECT_NE(s.health.reason.find("flickered in and out of contact"), std::string::npos) << s.health.reason;
  EXPECT_EQ(rec.attrs.at("health_ok"), 0.0);
  EXPECT_NE(rec.text_attrs.at("health_reason").find("flickered in and out of contact"), std::string::npos)
      << rec.text_attrs.at("health_reason");
}

}  // namespace
}  // namespace tactip
