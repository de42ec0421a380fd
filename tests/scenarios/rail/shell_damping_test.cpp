// skin.shell_damping = gel: the shell skin's in-plane damper follows the mass it carries, so the
// held object's mode and the released shell's mode both have the damping ratio of the gel's loss
// tangent (tan delta / 2), where a fixed damper leaves the held object ringing.

#include "sensors/shell_damping.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <mujoco/mujoco.h>

#include "models/skin.h"
#include "scenarios/rail/rail.h"
#include "scenarios/rail/rail_run.h"

namespace tactip {
namespace {

// The MJCF prefixes of the config's sensors, in order.
std::vector<std::string> Prefixes(const RailScenarioConfig& cfg) {
  std::vector<std::string> out;
  for (const SensorMountConfig& mount : cfg.sensors) out.push_back(mount.Prefix());
  return out;
}

// A gel shell damped at `ratio` (loss tangent 2 x ratio), 1 ms throughout (its validated
// sliding step); a viscous one at the same ratio. Both on the lumped shell (gel shear modulus
// E_gel / 3, 1650 N/m), where the gel damper was characterised: on the default 10 kPa shell
// (495 N/m, 5.4 Hz with 0.4 kg held) a 0.4 kg object held on the gel at a ratio of 0.1 still
// rings, its fastest pin at 1.09 px/frame over the 0.5 s hold (docs/model.md, 'The pin-lattice
// skin').
RailScenarioConfig Gel(double ratio) {
  RailScenarioConfig c;
  c.skin.gel_shear_modulus_kpa = 0.0;
  c.skin.shell_damping = "gel";
  c.skin.gel_loss_tangent = 2.0 * ratio;
  c.sim.timestep_s = kLightShellValidatedStepS;
  return c;
}
RailScenarioConfig Viscous(double ratio) {
  RailScenarioConfig c;
  c.skin.gel_shear_modulus_kpa = 0.0;
  c.skin.shell_damping = "viscous";
  c.skin.shear_damping_ratio = ratio;
  c.sim.timestep_s = kLightShellValidatedStepS;
  return c;
}

TEST(ShellDampingTest, TheGelsRatioIsHalfItsLossTangentAndALightShellIsRefusedAboveItsValidatedSlidingStep) {
  EXPECT_DOUBLE_EQ(Gel(0.08).skin.ShellDampingRatio(), 0.08);
  EXPECT_DOUBLE_EQ(Viscous(4.0).skin.ShellDampingRatio(), 4.0);
  EXPECT_DOUBLE_EQ(RailScenarioConfig{}.skin.ShellDampingRatio(), 4.0);  // the default: viscous
  Gel(0.08).ValidateRules();
  // Held at 2 ms, sliding at the default 1 ms: accepted.
  RailScenarioConfig coarse = Gel(0.08);
  coarse.sim.timestep_s = 0.002;
  coarse.ValidateRules();
  // Sliding at 2 ms too: refused.
  coarse.sim.sliding_timestep_s = 0.0;
  try {
    coarse.ValidateRules();
    FAIL() << "the gel shell sliding at 2 ms was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "sim.sliding_timestep_s = 0: the shell skin damped at a ratio of 0.08 (skin.gel_loss_tangent / 2; below "
              "0.5) is validated with a step up to 0.001 s from the gross-slip onset on (here 0.002 s): at larger "
              "steps the released shell's ringing makes the sliding contacts chatter; use sim.sliding_timestep_s <= "
              "0.001 (not 0) or sim.timestep_s <= 0.001");
  }
  // A sliding step above 1 ms still slides at a whole fraction of the step: 2 ms / 2 is
  // accepted, 2.5 ms / 2 = 1.25 ms refused.
  coarse.sim.sliding_timestep_s = 0.0015;
  coarse.ValidateRules();
  coarse.sim.timestep_s = 0.0025;
  EXPECT_THROW(coarse.ValidateRules(), InputError);
  // A fixed damper as light is refused alike; from a ratio of 0.5 on a 2 ms slide is fine.
  RailScenarioConfig fixed = Viscous(0.3), firm = Viscous(0.5);
  fixed.sim.timestep_s = firm.sim.timestep_s = 0.002;
  fixed.sim.sliding_timestep_s = firm.sim.sliding_timestep_s = 0.0;
  EXPECT_THROW(fixed.ValidateRules(), InputError);
  firm.ValidateRules();
}

// Damping ratio of the shell's in-plane mode carrying `mass_kg` with damper `c`.
double Ratio(const RailScenarioConfig& cfg, int n_pins, double c, double mass_kg) {
  const SkinMechanics mech = SkinMechanics::From(cfg.skin, static_cast<size_t>(n_pins));
  const double k = n_pins * mech.k_shear_N_m;
  return c / (2.0 * std::sqrt(k * mass_kg));
}

// What the shell's joints carry, from the compiled model's body masses: the shell body
// with every pin under it.
double ShellMovingMass(const CompiledModel& model, const std::string& sensor) {
  return model.raw()->body_subtreemass[model.BodyId(sensor + "/skin_shell")];
}

TEST(ShellDampingTest, EveryModeOfTheGelShellAlongTheRailHasTheConfiguredRatioWhateverItCarries) {
  const RailScenarioConfig cfg = Gel(0.1);
  const RailScene ids(cfg, SceneOptions{});
  CompiledModel model = ids.scene.model->Copy();
  const int n = ids.scene.built.n_pins;
  ShellDamping damping(cfg.skin, cfg.object.mass_kg, Prefixes(cfg), model, n);
  ASSERT_TRUE(damping.active());
  const int dof_y = model.JointDofAdr(model.JointId("tactip/skin_shear_y"));
  const int dof_z = model.JointDofAdr(model.JointId("tactip/skin_shear_z"));
  const double shell = ShellMovingMass(model, "tactip");
  const double object = cfg.object.mass_kg;
  const double c_y = model.DofDamping(dof_y);

  damping.Update({1.0});  // every contact sticks: the shell carries the whole object along the rail
  EXPECT_NEAR(Ratio(cfg, n, model.DofDamping(dof_z), shell + object), 0.1, 1e-6);
  EXPECT_EQ(model.DofDamping(dof_y), c_y);  // across the rail the object does not move
  damping.Update({0.5});  // half the contacting pins stick: half the object
  EXPECT_NEAR(Ratio(cfg, n, model.DofDamping(dof_z), shell + 0.5 * object), 0.1, 1e-6);
  damping.Update({0.0});  // sliding or no contact: the shell alone
  EXPECT_NEAR(Ratio(cfg, n, model.DofDamping(dof_z), shell), 0.1, 1e-6);
  EXPECT_NEAR(Ratio(cfg, n, ids.scene.model->DofDamping(dof_z), shell), 0.1, 1e-6);  // the compiled damper
}

TEST(ShellDampingTest, TwoSensorsWithStuckContactsShareTheObject) {
  RailScenarioConfig cfg = Gel(0.1);
  cfg.sensors = {SensorMountConfig{"left", -25.0}, SensorMountConfig{"right", 25.0}};
  const RailScene ids(cfg, SceneOptions{});
  CompiledModel model = ids.scene.model->Copy();
  const int n = ids.scene.built.n_pins;
  ShellDamping damping(cfg.skin, cfg.object.mass_kg, Prefixes(cfg), model, n);
  const int left = model.JointDofAdr(model.JointId("left/skin_shear_z"));
  const int right = model.JointDofAdr(model.JointId("right/skin_shear_z"));
  const double shell = ShellMovingMass(model, "left");
  const double object = cfg.object.mass_kg;

  damping.Update({1.0, 1.0});
  EXPECT_NEAR(Ratio(cfg, n, model.DofDamping(left), shell + 0.5 * object), 0.1, 1e-6);
  EXPECT_NEAR(Ratio(cfg, n, model.DofDamping(right), shell + 0.5 * object), 0.1, 1e-6);
  damping.Update({1.0, 0.5});  // the right one half stuck: a quarter of the object
  EXPECT_NEAR(Ratio(cfg, n, model.DofDamping(left), shell + 0.5 * object), 0.1, 1e-6);
  EXPECT_NEAR(Ratio(cfg, n, model.DofDamping(right), shell + 0.25 * object), 0.1, 1e-6);
  damping.Update({1.0, 0.0});  // only the left one sticks
  EXPECT_NEAR(Ratio(cfg, n, model.DofDamping(left), shell + object), 0.1, 1e-6);
  EXPECT_NEAR(Ratio(cfg, n, model.DofDamping(right), shell), 0.1, 1e-6);
}

TEST(ShellDampingTest, AViscousShellKeepsItsFixedDamperAndAMembraneSkinIgnoresTheGel) {
  const RailScenarioConfig viscous = Viscous(0.1);
  const RailScene ids(viscous, SceneOptions{});
  CompiledModel model = ids.scene.model->Copy();
  ShellDamping damping(viscous.skin, viscous.object.mass_kg, Prefixes(viscous), model, ids.scene.built.n_pins);
  EXPECT_FALSE(damping.active());
  const int dof = model.JointDofAdr(model.JointId("tactip/skin_shear_y"));
  const double before = model.DofDamping(dof);
  damping.Update({1.0});
  EXPECT_EQ(model.DofDamping(dof), before);

  // A lattice damps each pin by shear_damping_ratio, whatever the shell's damper.
  RailScenarioConfig gel_lattice = Gel(0.1), viscous_lattice = Viscous(0.1);
  for (RailScenarioConfig* c : {&gel_lattice, &viscous_lattice}) {
    c->skin.coupling = "membrane";
    c->skin.shear_damping_ratio = 4.0;
    c->skin.ValidateRules();
  }
  const SkinMechanics a = SkinMechanics::From(gel_lattice.skin, 127), b = SkinMechanics::From(viscous_lattice.skin, 127);
  EXPECT_DOUBLE_EQ(a.tip_damping_Ns_m, b.tip_damping_Ns_m);
  const RailScene lattice(gel_lattice, SceneOptions{});
  CompiledModel lattice_model = lattice.scene.model->Copy();
  EXPECT_FALSE(ShellDamping(gel_lattice.skin, gel_lattice.object.mass_kg, Prefixes(gel_lattice), lattice_model,
                            lattice.scene.built.n_pins)
                   .active());
}

// Noise-free rail runs; `lift_mm` 50 lifts the plate's edge above the contact, so that the
// object slides off it after the onset (20: it lands on its end stop still touching).
RailScenarioConfig Quiet(RailScenarioConfig c, const char* stimulus, double mass_kg, double depth_mm,
                         double speed_mm_s, double lift_mm = 20.0) {
  c.rail.stimulus = stimulus;
  c.object.mass_kg = mass_kg;
  c.rail.press_depth_mm = depth_mm;
  c.rail.lift_mm = lift_mm;
  c.rail.retract_speed_mm_s = speed_mm_s;
  c.sensor.pixel_noise_px = 0.0;
  c.sensor.noise_model = "independent";
  c.sensor.dropout_prob = 0.0;
  return c;
}

// The fastest any pin moves, px/frame, over the hold between the lift and the retraction
// (the sensor still, the object held): the held object's ringing, seen by the camera.
double HoldPinSpeedPx(const RunRecord& rec, double hold_s) {
  const SensorRecord& s = rec.sensors[0];
  const size_t n = static_cast<size_t>(s.n_pins);
  const double end = rec.attrs.at("retract_start_s"), start = end - hold_s;
  double fastest = 0.0;
  for (size_t f = 1; f < rec.frames(); ++f) {
    if (rec.time[f - 1] < start || rec.time[f] > end) continue;
    for (size_t i = 0; i < n; ++i) {
      const size_t a = 2 * ((f - 1) * n + i), b = 2 * (f * n + i);
      fastest = std::max(fastest, static_cast<double>(std::hypot(s.pos_px[b] - s.pos_px[a], s.pos_px[b + 1] - s.pos_px[a + 1])));
    }
  }
  return fastest;
}

TEST(ShellDampingTest, AHeavyHeldObjectRingsOnALightFixedDamperButNotOnTheGel) {
  // The shell's ratio 0.1 with 0.4 kg held: a fixed damper gives the held mode 0.025. Run
  // health does not flag the ringing (the pins move with the object they stick to: physics,
  // not a numerical defect), so the camera's pin speed over the hold is measured directly.
  const RailScenarioConfig viscous = Viscous(0.1);
  RunRecord rings, still;
  const RailScenarioConfig ringing = Quiet(viscous, "curved80", 0.4, 4.5, 0.2);
  RailScenario(ringing).Run(0, 3, rings);
  EXPECT_GT(HoldPinSpeedPx(rings, ringing.rail.hold_s), 0.6);  // 0.96 px/frame measured (f = 377 px)
  const RailScenarioConfig gel = Quiet(Gel(0.1), "curved80", 0.4, 4.5, 0.2);
  const RailRunSummary held = RailScenario(gel).Run(0, 3, still);
  EXPECT_TRUE(held.health.ok) << held.health.reason;
  EXPECT_LT(HoldPinSpeedPx(still, gel.rail.hold_s), 0.1);
}

TEST(ShellDampingTest, TheGelHoldsAHeavyObjectStillAtTheDefaultStep) {
  // The held phase at 2 ms (the sliding step takes the gross slip): the same hold as above.
  RailScenarioConfig coarse = Gel(0.1);
  coarse.sim.timestep_s = 0.002;
  const RailScenarioConfig gel = Quiet(coarse, "curved80", 0.4, 4.5, 0.2);
  RunRecord still;
  const RailRunSummary held = RailScenario(gel).Run(0, 3, still);
  EXPECT_TRUE(held.health.ok) << held.health.reason;
  EXPECT_LT(HoldPinSpeedPx(still, gel.rail.hold_s), 0.1);
}

// Frames in a row, from the frame after the onset's (whose motion spans the onset), whose mean
// pin speed exceeds `level_px`; and the frames from there to the first with no pin in contact.
struct Spike {
  int above = 0, to_contact_loss = 0;
};
Spike SpikeOf(const RunRecord& rec, double onset_s, double level_px) {
  const SensorRecord& s = rec.sensors[0];
  const size_t n = static_cast<size_t>(s.n_pins);
  const size_t first =
      static_cast<size_t>(std::lower_bound(rec.time.begin(), rec.time.end(), onset_s) - rec.time.begin()) + 1;
  Spike spike;
  bool running = true;
  for (size_t f = first; f < rec.frames(); ++f) {
    double sum = 0.0;
    size_t touching = 0;
    for (size_t i = 0; i < n; ++i) {
      sum += std::hypot(s.pos_px[2 * (f * n + i)] - s.pos_px[2 * ((f - 1) * n + i)],
                        s.pos_px[2 * (f * n + i) + 1] - s.pos_px[2 * ((f - 1) * n + i) + 1]);
      touching += s.pin_contact[f * n + i];
    }
    running = running && sum / static_cast<double>(n) > level_px;
    if (running) ++spike.above;
    if (touching == 0) {
      spike.to_contact_loss = static_cast<int>(f - first);
      break;
    }
  }
  return spike;
}

TEST(ShellDampingTest, ReleasedGelShellKeepsThePinsMovingLongerThanAViscousOne) {
  // Measured at the gel's validated step (1 ms): 6 of the 12 frames to contact loss above the
  // noise level, against 2 of 11 for the viscous shell. Not until contact is lost: at 2 ms the
  // chattering sliding contacts had filled every frame (docs/fingerprint-skins.md, 'Slip
  // signatures against the hardware').
  // 0.57 px/frame: the level the default camera noise puts on the mean pin speed
  // (docs/viewer-and-plots.md, 'The figure gallery').
  constexpr double kNoiseLevelPx = 0.57;
  RunRecord viscous_rec, gel_rec;
  const RailRunSummary viscous =
      RailScenario(Quiet(Viscous(4.0), "flat", 0.1, 3.0, 1.0, 50.0)).Run(0, 3, viscous_rec);
  const RailRunSummary gel = RailScenario(Quiet(Gel(0.05), "flat", 0.1, 3.0, 1.0, 50.0)).Run(0, 3, gel_rec);
  ASSERT_TRUE(viscous.health.ok && gel.health.ok) << viscous.health.reason << gel.health.reason;
  ASSERT_FALSE(std::isnan(viscous.gross_slip_onset_s) || std::isnan(gel.gross_slip_onset_s));
  const Spike overdamped = SpikeOf(viscous_rec, viscous.gross_slip_onset_s, kNoiseLevelPx);
  const Spike ringing = SpikeOf(gel_rec, gel.gross_slip_onset_s, kNoiseLevelPx);
  ASSERT_GT(ringing.to_contact_loss, 8);
  EXPECT_GE(ringing.above, 2 * overdamped.above + 1);
  EXPECT_GE(ringing.above, ringing.to_contact_loss / 3);
  EXPECT_LT(overdamped.above, overdamped.to_contact_loss / 2);
}

}  // namespace
}  // namespace tactip
