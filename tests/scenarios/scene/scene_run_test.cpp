// The scene run on a scene no protocol of the project has, built only from generic parts:
// a small 37-pin TacTip named "finger" pressed on a 40 g box (on a vertical slide joint,
// standing on its end stop) by a slider, lifted by a second slider it rides on, then
// retracted until the box falls. The step loop runs it unchanged.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <span>
#include <string>
#include <vector>

#include "models/parts.h"
#include "models/rail_rig.h"
#include "scenarios/rail/rail_schedule.h"
#include "scenarios/scene/scene.h"
#include "scenarios/scene/scene_run.h"
#include "sensors/gel_field.h"
#include "tests/mujoco_warning_guard.h"

namespace tactip {
namespace {

constexpr double kGapM = 1e-3, kPressM = 2e-3, kLiftM = 5e-3, kRetractM_s = 5e-3;
constexpr double kMassKg = 0.04;

SkinConfig SmallSkin() {
  SkinConfig skin;
  skin.rings = 3;  // 37 pins
  return skin;
}

// The box (its face in the plane x = 0), and the finger on the lift slider on the press slider.
BuiltScene BoxScene(const SimConfig& sim, const ContactConfig& contact, const SkinConfig& skin) {
  BoxObjectSpec box;
  box.pos = {0.005, 0.0, 0.1};
  box.half_size = {0.005, 0.025, 0.025};
  box.mass_kg = kMassKg;
  box.range_m = {0.0, 0.1};
  box.contact = contact;
  const PinLattice lattice = PinLattice::Build(skin);
  const std::vector<bool> every(lattice.size(), true);
  SensorMountSpec finger;
  finger.name = "finger";
  finger.carrier_joint = "lift";
  finger.press_servo = "press_servo";
  std::vector<ScenePart> on_lift;
  on_lift.push_back(SensorMountPart(
      finger, BuildSkin(skin, contact, lattice, every, sim.timestep_s, every, SkinNames{"finger/"}), every));
  const SliderSpec lift{"lift_stage", "lift", "lift_servo", {}, {0, 0, 1}, 0.3, 1e-3, 1e5, 400.0};
  SliderSpec press{"press_stage", "press", "press_servo", {}, {1, 0, 0}, 0.3, 1e-3, 1e5, 500.0};
  press.pos = {-skin.OuterRadiusMm() * 1e-3 - kGapM, 0.0, 0.1};
  std::vector<ScenePart> on_press;
  on_press.push_back(SliderPart(lift, std::move(on_lift)));
  std::vector<ScenePart> parts;
  parts.push_back(BoxObjectPart(box));
  parts.push_back(SliderPart(press, std::move(on_press)));
  const int n_collidable = parts[0].n_collidable + parts[1].n_collidable;
  return AssembleScene(SceneRoot("box_scene", sim, contact, -9.81, n_collidable), std::move(parts));
}

// Press, lift, hold, retract: the press servo's target first, the lift's second (the scene's
// actuator order).
class PressLiftRetract : public SceneController {
 public:
  void Controls(double t, std::span<double> out) override {
    out[0] = (kGapM + kPressM) * SmoothStep(t / 0.3) - kRetractM_s * std::max(0.0, t - kRetractS);
    out[1] = kLiftM * SmoothStep((t - kLiftS) / 0.2);
  }
  void OnFrame(const FrameInput& input) override {
    ++frames;
    pins = static_cast<int>(input.frames.front()->pos_px.size());
  }
  static constexpr double kLiftS = 0.4, kRetractS = 0.8;
  int frames = 0, pins = 0;
};

class SceneRunTest : public testing::MujocoWarningGuard {};

TEST_F(SceneRunTest, ASensorPressedOnABoxBySlidersRunsThroughTheSameStepLoop) {
  SimConfig sim;
  const ContactConfig contact;
  const SkinConfig skin = SmallSkin();
  const PinLattice lattice = PinLattice::Build(skin);
  TactileSensorSpec spec;
  spec.name = "finger";
  spec.gel_field = GelField::Build(skin, lattice);
  spec.apex_x_m = skin.OuterRadiusMm() * 1e-3;
  const Scene scene = Scene::Compile(BoxScene(sim, contact, skin), {spec}, {skin});
  ASSERT_EQ(scene.actuators.size(), 2u);
  EXPECT_EQ(scene.actuators[0].name, "press_servo");
  EXPECT_EQ(scene.object.name, "box");
  EXPECT_EQ(scene.sensors[0].n_pins, 37);
  EXPECT_EQ(scene.sensors[0].press_actuator, 0);

  SceneRunSettings settings;
  settings.sim = sim;
  settings.contact = contact;
  settings.limits = StateLimits::For(skin, kPressM * 1e3, kMassKg * 9.81, 37);
  ProtocolTimeline timeline;
  timeline.load_s = PressLiftRetract::kLiftS;
  timeline.held_s = PressLiftRetract::kLiftS + 0.2;
  timeline.release_s = PressLiftRetract::kRetractS;
  timeline.give_up_s = 2.0;
  timeline.after_loss_s = 0.1;
  PressLiftRetract controller;
  RunRecord rec;
  SceneRun run(scene, settings, timeline, RunDraws{0, 7, contact.friction}, controller);
  const SceneRunSummary s = run.Execute(rec, nullptr);

  // Every frame recorded and shown to the controller, with the scene's own names.
  ASSERT_EQ(rec.sensors.size(), 1u);
  EXPECT_EQ(rec.sensors[0].name, "finger");
  EXPECT_EQ(rec.actions.actuators, (std::vector<std::string>{"press_servo", "lift_servo"}));
  EXPECT_EQ(controller.frames, static_cast<int>(rec.frames()));
  EXPECT_EQ(controller.pins, 2 * 37);
  // The box is held through the lift, then slips on the finger during the retraction: one
  // sensor, so it slips on it when it slips on all of them; it falls, the run ends after.
  EXPECT_EQ(s.object, "box");
  EXPECT_TRUE(s.held);
  ASSERT_FALSE(std::isnan(s.gross_slip_onset_s));
  EXPECT_GT(s.gross_slip_onset_s, timeline.release_s);
  ASSERT_EQ(s.slip_on_sensor_s.size(), 1u);
  EXPECT_EQ(s.slip_on_sensor_s[0], s.gross_slip_onset_s);
  EXPECT_FALSE(std::isnan(s.object_fall_s));
  EXPECT_LT(rec.time.back(), s.object_fall_s + timeline.after_loss_s + 0.02);
  // Coulomb: the box starts to slide within two frames of mu sum(N) falling below m g.
  ASSERT_FALSE(std::isnan(s.predicted_onset_s));
  EXPECT_NEAR(s.gross_slip_onset_s, s.predicted_onset_s, 0.02);
  EXPECT_TRUE(s.health.ok) << s.health.reason;
  EXPECT_EQ(rec.attrs.at("object_mass_kg"), kMassKg);
}

}  // namespace
}  // namespace tactip
