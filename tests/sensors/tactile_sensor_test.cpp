#include "sensors/tactile_sensor.h"

#include <gtest/gtest.h>

#include <cmath>

#include "models/pin_lattice.h"
#include "models/rail_rig.h"
#include "sensors/camera_presets.h"
#include "sensors/friction_law.h"
#include "sim/config.h"

namespace tactip {
namespace {

// The rail scene with the default TacTip, compiled; the pins that can reach a 3 mm press
// carry contact geoms.
struct RailModel {
  RailSceneSpec spec;
  BuiltScene scene;
  CompiledModel model;
  TactileSensorIds ids;

  RailModel() : spec(Spec()), scene(BuildRailScene(spec)), model(CompiledModel::FromXml(scene.xml)) {
    ids = TactileSensorIds::Find(model, RailNames::SensorMount("tactip"), scene.n_pins,
                                 RailOuterSitePins(spec, static_cast<size_t>(scene.n_pins)), SkinNames{"tactip/"});
  }
  static RailSceneSpec Spec() {
    RailSceneSpec s;
    s.max_depth_m = 3e-3;
    return s;
  }
};

TactileSensorSpec NoiseFree() {
  TactileSensorSpec spec;
  spec.camera.pixel_noise_px = 0.0;
  spec.camera.noise_model = "independent";
  spec.camera.dropout_prob = 0.0;
  return spec;
}

TEST(TactileSensorTest, FindsEveryPinAndCullsThoseThatCannotTouch) {
  const RailModel rail;
  ASSERT_EQ(static_cast<int>(rail.ids.pin_site.size()), rail.scene.n_pins);
  int with_geom = 0;
  for (int i = 0; i < rail.scene.n_pins; ++i) {
    if (rail.ids.pin_geom[i] < 0) continue;
    ++with_geom;
    EXPECT_EQ(rail.ids.slot_of_geom[rail.ids.pin_geom[i]], i);
  }
  EXPECT_EQ(with_geom, rail.scene.n_collidable);
  EXPECT_LT(with_geom, rail.scene.n_pins);  // the rim cannot reach a 3 mm press
}

TEST(TactileSensorTest, AtRestNothingTouchesAndTheNoiseFreeFrameIsTheProjection) {
  const RailModel rail;
  Simulation sim(rail.model);
  sim.Forward();
  TactileSensor sensor(NoiseFree(), rail.ids, 1, 2);
  sensor.Rest(sim);
  sensor.ReadContacts(sim);
  EXPECT_EQ(sensor.labels().n_contact, 0);
  const PinFrame& frame = sensor.Capture(sim, 0.25);
  const SensorReading& rec = sensor.reading();
  ASSERT_EQ(frame.size(), rail.scene.n_pins);
  EXPECT_EQ(frame.time_s, 0.25);
  // The camera looks along the dome axis: the centre pin at the principal point, every pin
  // inside the image, all detected; the reading holds one frame of every per-pin array.
  const CameraConfig& cam = NoiseFree().camera;
  EXPECT_NEAR(frame.pos_px(0, 0), cam.cx_px, 1e-3);
  EXPECT_NEAR(frame.pos_px(0, 1), cam.cy_px, 1e-3);
  for (int i = 0; i < frame.size(); ++i) {
    EXPECT_EQ(frame.valid[i], 1);
    EXPECT_GT(frame.pos_px(i, 0), 0.0);
    EXPECT_LT(frame.pos_px(i, 0), cam.width_px);
  }
  const size_t n = static_cast<size_t>(rail.scene.n_pins);
  EXPECT_EQ(rec.pos_px.size(), 2 * n);
  EXPECT_EQ(rec.pos_m.size(), 3 * n);
  EXPECT_EQ(rec.pin_contact.size(), n);
  EXPECT_EQ(rec.incipient, 0);
  EXPECT_TRUE(rec.external_px.empty());  // no external camera unless enabled
  for (double s : sensor.marker_shift_m()) EXPECT_EQ(s, 0.0);
}

TEST(TactileSensorTest, CameraNoiseMovesTheReportedButNotTheCleanPositions) {
  const RailModel rail;
  Simulation sim(rail.model);
  sim.Forward();
  TactileSensorSpec noisy = NoiseFree();
  noisy.camera.pixel_noise_px = 0.5;
  TactileSensor sensor(noisy, rail.ids, 1, 2);
  sensor.Rest(sim);
  sensor.ReadContacts(sim);
  const PinFrame& frame = sensor.Capture(sim, 0.0);
  double sum_sq = 0.0;
  for (int i = 0; i < frame.size(); ++i) {
    for (int k = 0; k < 2; ++k) {
      const double d = frame.pos_px(i, k) - sensor.clean_px()[2 * i + k];
      sum_sq += d * d;
    }
  }
  const double rms = std::sqrt(sum_sq / (2.0 * frame.size()));
  EXPECT_GT(rms, 0.3);
  EXPECT_LT(rms, 0.7);
}

TEST(FrictionLawTest, SlidingPinDropsToKineticAndSticksBack) {
  RailModel rail;
  ContactConfig contact;
  contact.kinetic_ratio = 0.6;
  contact.pin_friction_spread = 0.0;
  const LabelConfig labels;
  FrictionLaw law(contact, labels, 1.0, rail.ids.pin_geom, rail.model.GeomId(RailNames::kStimulus), 7,
                  rail.model);
  int pin = 0;
  while (rail.ids.pin_geom[pin] < 0) ++pin;
  const int geom = rail.ids.pin_geom[pin];
  EXPECT_DOUBLE_EQ(rail.model.GeomFriction(geom), 1.0);
  EXPECT_DOUBLE_EQ(rail.model.GeomFriction(rail.model.GeomId(RailNames::kStimulus)), 0.6);
  const size_t n = rail.ids.pin_geom.size();
  std::vector<PinContactSample> samples(n, PinContactSample{true, 0.0, 0.5});
  std::vector<std::uint8_t> slip(n, 0);
  slip[pin] = 1;
  samples[pin].slip_speed_m_s = 1e-3;
  law.Update(samples, slip, rail.model);
  EXPECT_DOUBLE_EQ(rail.model.GeomFriction(geom), 0.6);
  // Still sliding above the slip tolerance after its label clears: stays kinetic.
  slip[pin] = 0;
  law.Update(samples, slip, rail.model);
  EXPECT_DOUBLE_EQ(rail.model.GeomFriction(geom), 0.6);
  // Stuck again: static.
  samples[pin].slip_speed_m_s = 0.0;
  law.Update(samples, slip, rail.model);
  EXPECT_DOUBLE_EQ(rail.model.GeomFriction(geom), 1.0);
}

TEST(FrictionLawTest, VelocityWeakeningIsHalfwayAtTheWeakeningSpeed) {
  RailModel rail;
  ContactConfig contact;
  contact.kinetic_ratio = 0.6;
  contact.weakening_speed_mm_s = 1.0;
  FrictionLaw law(contact, LabelConfig{}, 1.0, rail.ids.pin_geom, rail.model.GeomId(RailNames::kStimulus), 7,
                  rail.model);
  const size_t n = rail.ids.pin_geom.size();
  std::vector<PinContactSample> samples(n, PinContactSample{true, 1e-3, 1.0});
  law.Update(samples, std::vector<std::uint8_t>(n, 1), rail.model);
  int pin = 0;
  while (rail.ids.pin_geom[pin] < 0) ++pin;
  EXPECT_NEAR(rail.model.GeomFriction(rail.ids.pin_geom[pin]), 0.8, 1e-12);
}

TEST(FrictionLawTest, SlipMemoryWeakensOverTheSlipDistanceAndResetsOutOfContact) {
  RailModel rail;
  ContactConfig contact;
  contact.kinetic_ratio = 0.6;
  contact.weakening_speed_mm_s = 1.0;
  contact.slip_memory_um = 10.0;
  FrictionLaw law(contact, LabelConfig{}, 1.0, rail.ids.pin_geom, rail.model.GeomId(RailNames::kStimulus), 7,
                  rail.model);
  int pin = 0;
  while (rail.ids.pin_geom[pin] < 0) ++pin;
  const int geom = rail.ids.pin_geom[pin];
  const size_t n = rail.ids.pin_geom.size();
  // Sliding at v_c = 1 mm/s, whose memoryless value is 0.8: 1 um per 1 ms step (the model's).
  rail.model.SetTimestep(1e-3);
  std::vector<PinContactSample> samples(n, PinContactSample{true, 1e-3, 1.0});
  const std::vector<std::uint8_t> slipping(n, 1), stuck(n, 0);
  law.Update(samples, slipping, rail.model);
  EXPECT_NEAR(rail.model.GeomFriction(geom), 0.8 + 0.2 * std::exp(-0.1), 1e-12);
  for (int k = 1; k < 10; ++k) law.Update(samples, slipping, rail.model);
  // After one memory length of slip the excess over 0.8 has fallen to 1/e.
  EXPECT_NEAR(rail.model.GeomFriction(geom), 0.8 + 0.2 * std::exp(-1.0), 1e-12);
  // A step changed mid-run is followed: 5 ms at 1 mm/s is half a memory length more.
  rail.model.SetTimestep(5e-3);
  law.Update(samples, slipping, rail.model);
  EXPECT_NEAR(rail.model.GeomFriction(geom), 0.8 + 0.2 * std::exp(-1.5), 1e-12);
  // Stuck again: the coefficient stays where the slip left it (no healing).
  for (auto& s : samples) s.slip_speed_m_s = 0.0;
  law.Update(samples, stuck, rail.model);
  EXPECT_NEAR(rail.model.GeomFriction(geom), 0.8 + 0.2 * std::exp(-1.5), 1e-12);
  // Out of contact: back to the static coefficient.
  for (auto& s : samples) s.in_contact = false;
  law.Update(samples, stuck, rail.model);
  EXPECT_DOUBLE_EQ(rail.model.GeomFriction(geom), 1.0);
}

TEST(FrictionLawTest, PerPinSpreadStaysInItsBandAndTheStimulusBelowEveryKineticValue) {
  RailModel rail;
  ContactConfig contact;
  contact.kinetic_ratio = 0.6;
  contact.pin_friction_spread = 0.2;
  FrictionLaw law(contact, LabelConfig{}, 1.0, rail.ids.pin_geom, rail.model.GeomId(RailNames::kStimulus), 7,
                  rail.model);
  double lo = 10.0, hi = 0.0;
  for (double mu : law.static_mu()) {
    lo = std::min(lo, mu);
    hi = std::max(hi, mu);
  }
  EXPECT_GE(lo, 0.8);
  EXPECT_LE(hi, 1.2);
  EXPECT_GT(hi - lo, 0.1);  // 127 draws spread over the band
  EXPECT_NEAR(rail.model.GeomFriction(rail.model.GeomId(RailNames::kStimulus)), 0.48, 1e-12);
}

}  // namespace
}  // namespace tactip

namespace tactip {
namespace {

// The camera of preset `name`: its sensor.* keys applied to the defaults.
CameraConfig PresetKeys(const std::string& name) {
  const std::string prefix = "sensor.";
  std::vector<std::string> keys;
  for (const std::string& k : CameraPreset(name)) {
    if (k.rfind(prefix, 0) == 0) keys.push_back(k.substr(prefix.size()));
  }
  return LoadConfig<CameraConfig>("", keys);
}

// The same with the noise off.
CameraConfig PresetCamera(const std::string& name) {
  CameraConfig c = PresetKeys(name);
  c.noise_model = "independent";
  c.pixel_noise_px = 0.0;
  c.dropout_prob = 0.0;
  return c;
}

// Mean image distance of the outermost ring's pins from the principal point, at rest.
double OuterRingRadiusPx(const CameraConfig& cam) {
  const RailModel rail;
  Simulation sim(rail.model);
  sim.Forward();
  TactileSensorSpec spec = NoiseFree();
  spec.camera = cam;
  TactileSensor sensor(spec, rail.ids, 1, 2);
  sensor.Rest(sim);
  const PinFrame& frame = sensor.Capture(sim, 0.0);
  const PinLattice lattice = PinLattice::Build(rail.spec.skin);
  int outer = 0;
  for (const PinGeometry& p : lattice.pins) outer = std::max(outer, p.ring);
  double sum = 0.0;
  int n = 0;
  for (size_t i = 0; i < lattice.size(); ++i) {
    if (lattice.pins[i].ring != outer) continue;
    sum += std::hypot(frame.pos_px(static_cast<int>(i), 0) - cam.cx_px, frame.pos_px(static_cast<int>(i), 1) - cam.cy_px);
    ++n;
  }
  return sum / n;
}

// real-sensor.md section 1: the 127-pin TacTip's outer ring at 131 px in its 640x480 frames;
// the public pose datasets' 256x256 crops at ~84 px (section 5); within 5 %.
TEST(CameraPresetTest, TheDefaultCameraPutsTheOuterRingWhereTheRealTacTipHasIt) {
  const CameraConfig defaults;
  EXPECT_EQ(defaults.width_px, 640);
  EXPECT_EQ(defaults.height_px, 480);
  EXPECT_NEAR(OuterRingRadiusPx(PresetCamera("tactip-640x480")), 131.0, 0.05 * 131.0);
  CameraConfig plain = defaults;
  plain.pixel_noise_px = 0.0;
  EXPECT_NEAR(OuterRingRadiusPx(plain), 131.0, 0.05 * 131.0);
}

TEST(CameraPresetTest, ThePoseDatasetCropAndTheLegacyCamera) {
  const CameraConfig pose = PresetKeys("pose-dataset-256");
  EXPECT_EQ(pose.width_px, 256);
  EXPECT_EQ(pose.height_px, 256);
  EXPECT_NEAR(OuterRingRadiusPx(PresetCamera("pose-dataset-256")), 84.4, 0.05 * 84.4);
  // The legacy camera (f = 580 px) puts the ring ~1.54x further out.
  EXPECT_GT(OuterRingRadiusPx(PresetCamera("legacy")), 190.0);
  // Its noise is the independent 0.28 px of the datasets made before; the default is structured.
  EXPECT_EQ(PresetKeys("legacy").noise_model, "independent");
  EXPECT_EQ(PresetKeys("legacy").pixel_noise_px, 0.28);
  EXPECT_EQ(CameraConfig().noise_model, "structured");
  // The crop's noise scales with its pixels.
  EXPECT_NEAR(pose.pixel_noise_px / CameraConfig().pixel_noise_px, 84.4 / 131.0, 1e-3);
}

TEST(CameraPresetTest, AnUnknownPresetIsRefusedByName) {
  try {
    CameraPreset("gopro");
    FAIL() << "accepted an unknown camera";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'gopro': unknown camera"), std::string::npos) << e.what();
  }
  EXPECT_EQ(CameraPresetNames().front(), "tactip-640x480");
}

}  // namespace
}  // namespace tactip
