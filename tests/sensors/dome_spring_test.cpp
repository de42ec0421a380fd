// skin.normal_spring = dome: each pin's gel spring rests on the dome, so a pin sheared over
// the dome's surface does not load it. Analytic anchor: an uncoupled lattice sagging under
// its own weight, u_z = -m g / k_tip, sinks along the dome's tangent plane, u_x =
// -(n_z / n_x) u_z, and the sensor's gel field reads no compression from it.

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "models/skin.h"
#include "sensors/gel_field.h"
#include "sensors/tactile_sensor.h"
#include "sim/simulation.h"

namespace tactip {
namespace {

constexpr double kGravity = 9.81;

// An uncoupled smooth lattice (coupling none: every pin on its own normal and shear
// springs) hanging in a body named "sensor", gravity along -z.
struct HangingSkin {
  SkinConfig skin;
  PinLattice lattice;
  CompiledModel model;

  explicit HangingSkin(const std::string& normal_spring)
      : skin(Skin(normal_spring)), lattice(PinLattice::Build(skin)), model(CompiledModel::FromXml(Xml())) {}

  static SkinConfig Skin(const std::string& normal_spring) {
    SkinConfig s;
    s.coupling = "none";
    s.normal_spring = normal_spring;
    return s;
  }

  std::string Xml() const {
    const std::vector<bool> every(lattice.size(), true);
    const SkinPart part = BuildSkin(skin, ContactConfig{}, lattice, every, 2e-4);
    std::string tendons;
    for (const auto& t : part.tendons) tendons += t.ToXml(2);
    return fmt::format(
        "<mujoco model=\"hanging skin\"><option timestep=\"0.0002\" integrator=\"Euler\" gravity=\"0 0 {}\"/>"
        "<worldbody><body name=\"sensor\">{}</body></worldbody><tendon>{}</tendon></mujoco>",
        -kGravity, part.body.ToXml(2), tendons);
  }
};

// Each pin's marker displacement (sensor frame, m) after 1 s of sagging from rest, as the
// noise-free sensor reads it (gel field included), and its pin's own displacement.
struct Sag {
  std::vector<std::array<double, 3>> marker, pin;
};

Sag SagForOneSecond(const HangingSkin& h) {
  Simulation sim(h.model);
  sim.Forward();
  TactileSensorSpec spec;
  spec.camera.pixel_noise_px = 0.0;
  spec.camera.dropout_prob = 0.0;
  spec.gel_field = GelField::Build(h.skin, h.lattice);
  const int n = static_cast<int>(h.lattice.size());
  const TactileSensorIds ids = TactileSensorIds::Find(h.model, "sensor", n, std::vector<bool>(n, true));
  TactileSensor sensor(spec, ids, 1, 2);
  sensor.Rest(sim);
  std::vector<std::array<double, 3>> rest;
  for (int i = 0; i < n; ++i) rest.push_back(sim.SitePos(ids.pin_site[i]));
  for (int step = 0; step < 5000; ++step) sim.Step();
  sensor.ReadContacts(sim);
  sensor.Capture(sim, sim.time());
  Sag sag;
  const std::vector<float>& pos = sensor.reading().pos_m;
  for (int i = 0; i < n; ++i) {
    const auto now = sim.SitePos(ids.pin_site[i]);
    sag.pin.push_back({now[0] - rest[i][0], now[1] - rest[i][1], now[2] - rest[i][2]});
    sag.marker.push_back({pos[3 * i] - rest[i][0], pos[3 * i + 1] - rest[i][1], pos[3 * i + 2] - rest[i][2]});
  }
  return sag;
}

TEST(DomeSpringTest, PinsSagAlongTheDomeUnderTheirOwnWeightAndTheGelReadsNoCompression) {
  const HangingSkin h("dome");
  const SkinMechanics mech = SkinMechanics::From(h.skin, h.lattice);
  const double u_z = -mech.pin_mass_kg * kGravity / mech.k_tip_N_m;
  ASSERT_GT(std::abs(u_z), 1e-4) << "the sag must be large enough to measure";
  const Sag sag = SagForOneSecond(h);
  int receding = 0, advancing = 0;
  for (const PinGeometry& pin : h.lattice.pins) {
    SCOPED_TRACE(fmt::format("pin {} (n = {:.3f} {:.3f} {:.3f})", pin.index, pin.normal[0], pin.normal[1],
                             pin.normal[2]));
    const auto& d = sag.pin[pin.index];
    EXPECT_NEAR(d[2], u_z, 0.01 * std::abs(u_z));
    EXPECT_NEAR(d[1], 0.0, 1e-3 * std::abs(u_z));
    const double along_dome = -pin.normal[2] / pin.normal[0] * d[2];
    EXPECT_NEAR(d[0], along_dome, 0.01 * std::abs(u_z));
    // The lower (south) side recedes from a stimulus, the upper side advances.
    receding += pin.normal[2] < -0.1 && d[0] < -0.1 * std::abs(u_z) ? 1 : 0;
    advancing += pin.normal[2] > 0.1 && d[0] > 0.1 * std::abs(u_z) ? 1 : 0;
    // No column is compressed, so the gel moves no marker: the camera sees the pins' motion.
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(sag.marker[pin.index][k], d[k], 1e-7) << "axis " << k;
  }
  EXPECT_GT(receding, 10);
  EXPECT_EQ(receding, advancing);
}

// The axial springs (the default) hold each pin at its height: it sags straight down, and
// the gel field is unchanged by the key.
TEST(DomeSpringTest, AxialSpringsKeepEachPinsHeightAsItSags) {
  const HangingSkin h("axial");
  const SkinMechanics mech = SkinMechanics::From(h.skin, h.lattice);
  const double u_z = -mech.pin_mass_kg * kGravity / mech.k_tip_N_m;
  const Sag sag = SagForOneSecond(h);
  for (const PinGeometry& pin : h.lattice.pins) {
    SCOPED_TRACE(fmt::format("pin {}", pin.index));
    EXPECT_NEAR(sag.pin[pin.index][2], u_z, 0.01 * std::abs(u_z));
    EXPECT_NEAR(sag.pin[pin.index][0], 0.0, 1e-3 * std::abs(u_z));
  }
}

}  // namespace
}  // namespace tactip
