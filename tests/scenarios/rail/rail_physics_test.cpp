// Physics acceptance of the rail scenario against the analytic anchors of physics.md:
// the Coulomb slip threshold, no creep before it, free fall after release.

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <ostream>

#include "mujoco_warning_guard.h"
#include "scenarios/rail/rail.h"

namespace tactip {
namespace {

constexpr double kCreepLimitUm = 20.0;  // acceptance: creep before onset
constexpr double kFallTolerance = 0.02; // acceptance: free fall within 2 % of g

// A deterministic config without per-run variation or camera noise.
RailScenarioConfig Exact(double mass_kg, double mu, double speed_mm_s) {
  RailScenarioConfig c;
  c.object.mass_kg = mass_kg;
  c.contact.friction = mu;
  c.contact.friction_jitter = 0.0;
  c.rail.retract_speed_mm_s = speed_mm_s;
  c.rail.press_depth_jitter_mm = 0.0;
  c.rail.lift_mm = 20.0;
  c.sensor.pixel_noise_px = 0.0;
  c.sensor.noise_model = "independent";
  c.sensor.dropout_prob = 0.0;
  return c;
}

struct RailCase {
  double mass_kg, mu, speed_mm_s, depth_mm, rail_friction_N;
};

// Readable parameter in test output.
void PrintTo(const RailCase& k, std::ostream* os) {
  *os << "m=" << k.mass_kg << " kg, mu=" << k.mu << ", v=" << k.speed_mm_s << " mm/s, depth=" << k.depth_mm
      << " mm, F_rail=" << k.rail_friction_N << " N";
}

// Every rail run here must go without a MuJoCo warning (a warning also stops the run).
class CoulombOnsetTest : public testing::MujocoWarningGuard, public ::testing::WithParamInterface<RailCase> {};
class RailPhysicsTest : public testing::MujocoWarningGuard {};

TEST_P(CoulombOnsetTest, SlipStartsWithinOneFrameOfCoulombThresholdWithoutCreep) {
  const RailCase k = GetParam();
  RailScenarioConfig c = Exact(k.mass_kg, k.mu, k.speed_mm_s);
  c.rail.press_depth_mm = k.depth_mm;
  c.rail.friction_N = k.rail_friction_N;
  const RailScenario scenario(c);
  RunRecord rec;
  const RailRunSummary s = scenario.Run(0, 1, rec);
  const double frame = 1.0 / c.sensor.frame_rate_hz;
  ASSERT_FALSE(std::isnan(s.gross_slip_onset_s)) << "object never slipped";
  ASSERT_FALSE(std::isnan(s.predicted_onset_s)) << "mu * sum(N) + rail friction never fell below m g";
  EXPECT_GT(s.gross_slip_onset_s, s.retract_start_s) << "slipped before retraction (during the lift)";
  // The skin slides once mu * sum(N) drops below the load it carries. Static rail
  // friction (+-F_rail) shares the load in an undetermined way, so onset lies between
  // mu sum(N) = m g + F_rail and mu sum(N) = m g - F_rail (the full Coulomb threshold);
  // without rail friction the two coincide.
  EXPECT_GE(s.gross_slip_onset_s, s.coulomb_early_s - frame) << "earliest " << s.coulomb_early_s << " s";
  EXPECT_LE(s.gross_slip_onset_s, s.predicted_onset_s + frame)
      << "onset " << s.gross_slip_onset_s << " s vs Coulomb " << s.predicted_onset_s << " s";
  if (k.rail_friction_N == 0.0) {
    EXPECT_LE(std::abs(s.gross_slip_onset_s - s.predicted_onset_s), frame)
        << "onset " << s.gross_slip_onset_s << " s vs Coulomb " << s.predicted_onset_s << " s";
  }
  // The first frame labelled gross slip is at most two frames after the onset (the
  // release can bounce every pin off the stimulus for the frame right after it).
  size_t first = 0;
  while (first < rec.frames() && !(rec.time[first] >= s.retract_start_s && rec.sensors[0].gross_slip[first])) ++first;
  ASSERT_LT(first, rec.frames());
  EXPECT_GE(rec.time[first], s.gross_slip_onset_s - 1e-9);
  EXPECT_LT(rec.time[first], s.gross_slip_onset_s + 2.0 * frame + 1e-9);
  EXPECT_LT(s.creep_um, kCreepLimitUm);
  EXPECT_FALSE(std::isnan(s.object_fall_s));
}

INSTANTIATE_TEST_SUITE_P(MassFrictionSpeed, CoulombOnsetTest,
                         ::testing::Values(RailCase{0.10, 1.0, 0.1, 3.0, 0.0}, RailCase{0.05, 0.5, 1.0, 3.0, 0.0},
                                           RailCase{0.20, 1.0, 1.0, 3.0, 0.0}, RailCase{0.10, 2.0, 3.0, 2.0, 0.0},
                                           RailCase{0.30, 0.8, 0.5, 4.5, 0.0}, RailCase{0.10, 1.0, 0.1, 3.0, 0.005},
                                           RailCase{0.20, 0.6, 0.3, 4.0, 0.02}),
                         [](const ::testing::TestParamInfo<RailCase>& info) {
                           const RailCase& k = info.param;
                           std::string name = "m" + std::to_string(static_cast<int>(k.mass_kg * 1000)) + "g_mu" +
                                              std::to_string(static_cast<int>(k.mu * 10)) + "_v" +
                                              std::to_string(static_cast<int>(k.speed_mm_s * 10)) + "_Fr" +
                                              std::to_string(static_cast<int>(k.rail_friction_N * 1000));
                           return name;
                         });

TEST_F(RailPhysicsTest, ObjectFallsWithGravityAfterRelease) {
  // Frictionless, undamped rail; fast retraction releases the object high on the
  // rail; frames at 500 Hz sample the free flight.
  RailScenarioConfig c = Exact(0.1, 1.0, 20.0);
  c.rail.friction_N = 0.0;
  c.rail.damping_Ns_m = 0.0;
  c.rail.lift_mm = 60.0;
  c.rail.post_fall_s = 0.3;
  c.sensor.frame_rate_hz = 500.0;
  const RailScenario scenario(c);
  RunRecord rec;
  const RailRunSummary s = scenario.Run(0, 1, rec);
  ASSERT_FALSE(std::isnan(s.object_fall_s));
  // Free flight: after the last frame with any pin in contact, above the end stop.
  const size_t T = rec.frames(), N = static_cast<size_t>(rec.sensors[0].n_pins);
  size_t last_contact = 0;
  for (size_t f = 0; f < T; ++f) {
    for (size_t i = 0; i < N; ++i) {
      if (rec.sensors[0].pin_contact[f * N + i]) last_contact = f;
    }
  }
  std::vector<double> t, h;
  for (size_t f = last_contact + 2; f < T && rec.object_height_m[f] > 2e-3; ++f) {
    t.push_back(rec.time[f]);
    h.push_back(rec.object_height_m[f]);
  }
  ASSERT_GE(t.size(), 10u) << "too few free-flight frames";
  // Least-squares fit h = a + b t + c t^2 (centred time for conditioning).
  const double t0 = std::accumulate(t.begin(), t.end(), 0.0) / t.size();
  double S[5] = {0, 0, 0, 0, 0}, R[3] = {0, 0, 0};
  for (size_t i = 0; i < t.size(); ++i) {
    const double x = t[i] - t0;
    double p = 1.0;
    for (int k = 0; k < 5; ++k, p *= x) S[k] += p;
    R[0] += h[i];
    R[1] += h[i] * x;
    R[2] += h[i] * x * x;
  }
  // Solve the 3x3 normal equations by Cramer's rule.
  auto det3 = [](double a, double b, double c, double d, double e, double f, double g, double hh, double i) {
    return a * (e * i - f * hh) - b * (d * i - f * g) + c * (d * hh - e * g);
  };
  const double D = det3(S[0], S[1], S[2], S[1], S[2], S[3], S[2], S[3], S[4]);
  const double Dc = det3(S[0], S[1], R[0], S[1], S[2], R[1], S[2], S[3], R[2]);
  const double g_fit = -2.0 * Dc / D;
  EXPECT_NEAR(g_fit, 9.81, kFallTolerance * 9.81) << "fitted from " << t.size() << " frames";
}

TEST_F(RailPhysicsTest, DefaultConfigRunRaisesNoWarningAndIsDeterministic) {
  const RailScenarioConfig c;  // defaults, with per-run variation and noise
  const RailScenario scenario(c);
  RunRecord a, b;
  const RailRunSummary sa = scenario.Run(3, 7, a);
  scenario.Run(3, 7, b);
  EXPECT_FALSE(std::isnan(sa.gross_slip_onset_s));
  EXPECT_EQ(a.sensors[0].pos_px, b.sensors[0].pos_px);
  EXPECT_EQ(a.sensors[0].pos_m, b.sensors[0].pos_m);
  EXPECT_EQ(a.sensors[0].normal_N, b.sensors[0].normal_N);
  EXPECT_EQ(a.sensors[0].pin_slip, b.sensors[0].pin_slip);
  ASSERT_EQ(a.attrs.size(), b.attrs.size());
  for (const auto& [key, value] : a.attrs) {
    // NaN marks events that did not happen; it must be NaN in both.
    const double other = b.attrs.at(key);
    EXPECT_TRUE(value == other || (std::isnan(value) && std::isnan(other))) << key;
  }
  // Another run index gets other variations.
  RunRecord other;
  scenario.Run(4, 7, other);
  EXPECT_NE(other.attrs.at("press_depth_mm"), a.attrs.at("press_depth_mm"));
}

TEST_F(RailPhysicsTest, LabelsDoNotDependOnSlipTolerance) {
  // The gross onset agrees within a frame across a decade of tolerance, and the per-pin
  // labels up to the onset agree between 1e-5 and 1e-4 m/s. (A sticking contact gives
  // elastically by its pre-sliding displacement, at a few um/s while its load changes, so a
  // tolerance of ~1e-6 m/s reads that give as slip just before the onset; after the onset
  // the tolerance also decides when a pin switches to kinetic friction.)
  std::vector<RunRecord> recs(3);
  std::vector<double> onsets;
  const double tols[] = {1e-5, 3e-5, 1e-4};
  for (int k = 0; k < 3; ++k) {
    RailScenarioConfig c = Exact(0.1, 1.0, 1.0);
    c.labels.slip_speed_m_s = tols[k];
    onsets.push_back(RailScenario(c).Run(0, 1, recs[k]).gross_slip_onset_s);
  }
  EXPECT_NEAR(onsets[0], onsets[1], 0.01);
  EXPECT_NEAR(onsets[1], onsets[2], 0.01);
  const size_t N = static_cast<size_t>(recs[0].sensors[0].n_pins);
  for (int k : {1, 2}) {
    size_t differ = 0, contact = 0;
    for (size_t f = 0; f < recs[0].frames() && recs[0].time[f] <= onsets[0] + 0.01; ++f) {
      for (size_t i = 0; i < N; ++i) {
        contact += recs[0].sensors[0].pin_contact[f * N + i];
        differ += recs[k].sensors[0].pin_slip[f * N + i] != recs[0].sensors[0].pin_slip[f * N + i];
      }
    }
    EXPECT_LT(static_cast<double>(differ), 0.01 * contact) << "tolerance " << tols[k];
  }
}

TEST_F(RailPhysicsTest, UnstableTimestepIsRefusedWithSafeValue) {
  RailScenarioConfig c;
  c.sim.timestep_s = 0.004;
  c.contact.timeconst_s = 0.008;
  try {
    RailScenario s(c);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("sim.timestep_s = 0.004: unstable"), std::string::npos) << msg;
    EXPECT_NE(msg.find("use sim.timestep_s <="), std::string::npos) << msg;
  }
}

TEST_F(RailPhysicsTest, HardContactTouchDownIsRefusedWithSafeImpedanceAndTimestep) {
  // impedance_min 0.99 at 2 ms: the touch-down mode omega_0 = sqrt(99) / (0.99 * 4 ms) =
  // 2513 rad/s, limit 0.9 * 2 / omega_0 = 0.716 ms.
  RailScenarioConfig c;
  c.contact.impedance_min = 0.99;
  try {
    RailScenario s(c);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("sim.timestep_s = 0.002: unstable: exceeds the limit 0.000716 s of the contact's touch-down mode"),
              std::string::npos)
        << msg;
    EXPECT_NE(msg.find("use sim.timestep_s <= 0.000716 or contact.impedance_min <= 0.927"), std::string::npos) << msg;
  }
}

TEST_F(RailPhysicsTest, DefaultsAreValid) {
  RailScenarioConfig c;
  EXPECT_NO_THROW(ValidateConfig(c));
}

}  // namespace
}  // namespace tactip
