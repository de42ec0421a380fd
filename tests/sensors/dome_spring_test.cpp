// skin.normal_spring = dome: each pin's gel spring rests on the dome, so a pin sheared over
// the dome's surface does not load it. Analytic anchors on an uncoupled lattice under its
// own weight: sagging sideways (gravity -z), u_z = -m g / k_tip, each pin sinks along the
// dome's tangent plane, u_x = -(n_z / n_x) u_z, and the gel field reads no compression;
// pressed along the axis (gravity -x), each spring shortens by m g / k_n whatever the pin's
// shear, and the gel field reads exactly that.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
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
// springs) hanging in a body named "sensor", gravity along -z (sideways) or -x (into the gel).
struct HangingSkin {
  SkinConfig skin;
  PinLattice lattice;
  char down;
  CompiledModel model;

  HangingSkin(const std::string& normal_spring, char down_axis)
      : skin(Skin(normal_spring)), lattice(PinLattice::Build(skin)), down(down_axis), model(CompiledModel::FromXml(Xml())) {}

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
        "<mujoco model=\"hanging skin\"><option timestep=\"0.0002\" integrator=\"Euler\" gravity=\"{} 0 {}\"/>"
        "<worldbody><body name=\"sensor\">{}</body></worldbody><tendon>{}</tendon></mujoco>",
        down == 'x' ? -kGravity : 0.0, down == 'z' ? -kGravity : 0.0, part.body.ToXml(2), tendons);
  }
};

// Each pin's marker displacement (sensor frame, m) after 1 s of sagging from rest, as the
// noise-free sensor reads it (gel field included), and its pin's own displacement.
struct Sag {
  std::vector<std::array<double, 3>> marker, pin;
};

// The gel field's shift of every marker for these column compressions.
std::vector<std::array<double, 3>> GelShifts(const HangingSkin& h, const std::vector<double>& compression_m) {
  std::vector<std::array<double, 3>> shift;
  GelField::Build(h.skin, h.lattice).Shifts(compression_m, shift);
  return shift;
}

Sag SagForOneSecond(const HangingSkin& h) {
  Simulation sim(h.model);
  sim.Forward();
  TactileSensorSpec spec;
  spec.camera.pixel_noise_px = 0.0;
  spec.camera.noise_model = "independent";
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
  const HangingSkin h("dome", 'z');
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

// Pressed along the axis by its own weight, each pin's dome spring shortens by m g / k_n
// (its normal row: the spring alone carries the axial force) while the pin also slides
// outwards over the dome, u_y = (n_y / n_x) m g / k_tip; the gel field moves the markers by
// exactly the flow of those compressions, not of the larger axial displacements.
TEST(DomeSpringTest, PressedAlongTheAxisEachSpringShortensByItsLoadAndTheGelReadsThat) {
  const HangingSkin h("dome", 'x');
  const SkinMechanics mech = SkinMechanics::From(h.skin, h.lattice);
  const double f = mech.pin_mass_kg * kGravity;
  const Sag sag = SagForOneSecond(h);
  std::vector<double> compression(h.lattice.size(), f / mech.k_normal_N_m);
  const auto shift = GelShifts(h, compression);
  double largest_shift = 0.0;
  int outwards = 0;
  for (const PinGeometry& pin : h.lattice.pins) {
    SCOPED_TRACE(fmt::format("pin {}", pin.index));
    const auto& n = pin.normal;
    const auto& d = sag.pin[pin.index];
    const double u_y = n[1] / n[0] * f / mech.k_tip_N_m, u_z = n[2] / n[0] * f / mech.k_tip_N_m;
    EXPECT_NEAR(d[1], u_y, 0.01 * f / mech.k_tip_N_m);
    EXPECT_NEAR(d[2], u_z, 0.01 * f / mech.k_tip_N_m);
    // L = u_x + (n_y u_y + n_z u_z) / n_x = -m g / k_n.
    EXPECT_NEAR(d[0] + (n[1] * d[1] + n[2] * d[2]) / n[0], -f / mech.k_normal_N_m, 0.01 * f / mech.k_normal_N_m);
    outwards += std::hypot(u_y, u_z) > 0.5 * f / mech.k_normal_N_m ? 1 : 0;
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(sag.marker[pin.index][k] - d[k], shift[pin.index][k], 1e-3 * f / mech.k_normal_N_m) << "axis " << k;
      largest_shift = std::max(largest_shift, std::abs(shift[pin.index][k]));
    }
  }
  EXPECT_GT(outwards, 10) << "the outer pins must slide visibly";
  EXPECT_GT(largest_shift, 0.1 * f / mech.k_normal_N_m) << "the gel must move the markers measurably";
}

// The axial springs (the default) hold each pin at its height: it sags straight down, and
// with no column compressed the markers move with the pins.
TEST(DomeSpringTest, AxialSpringsKeepEachPinsHeightAsItSags) {
  const HangingSkin h("axial", 'z');
  const SkinMechanics mech = SkinMechanics::From(h.skin, h.lattice);
  const double u_z = -mech.pin_mass_kg * kGravity / mech.k_tip_N_m;
  const Sag sag = SagForOneSecond(h);
  for (const PinGeometry& pin : h.lattice.pins) {
    SCOPED_TRACE(fmt::format("pin {}", pin.index));
    EXPECT_NEAR(sag.pin[pin.index][2], u_z, 0.01 * std::abs(u_z));
    EXPECT_NEAR(sag.pin[pin.index][0], 0.0, 1e-3 * std::abs(u_z));
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(sag.marker[pin.index][k], sag.pin[pin.index][k], 1e-7) << "axis " << k;
  }
}

}  // namespace
}  // namespace tactip
