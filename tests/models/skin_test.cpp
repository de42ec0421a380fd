#include "models/skin.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <mujoco/mujoco.h>

#include "mujoco_warning_guard.h"
#include "models/rail_rig.h"
#include "sim/simulation.h"
#include "input_error.h"

namespace tactip {
namespace {

constexpr double kTol = 1e-9;

// Compiling a scene runs MuJoCo (its setup pass on a scratch mjData): no warning allowed.
class SkinTest : public testing::MujocoWarningGuard {};

TEST_F(SkinTest, DefaultsAreValid) {
  SkinConfig s;
  EXPECT_NO_THROW(ValidateConfig(s));
  ContactConfig c;
  EXPECT_NO_THROW(ValidateConfig(c));
}

TEST(ContactFrictionTest, BreakawayDropsASlidingPinAtOnceThenWeakensToKinetic) {
  ContactConfig c;
  c.kinetic_ratio = 0.5;
  c.weakening_speed_mm_s = 10.0;
  c.breakaway_ratio = 0.8;
  const double mu_s = 1.0, mu_b = 0.8, mu_k = 0.5;
  // A pin that has not broken away weakens from the static value, one that has from mu_b.
  EXPECT_NEAR(c.WeakenedFriction(mu_s, 0.0, false), mu_s, kTol);
  EXPECT_NEAR(c.WeakenedFriction(mu_s, 0.0, true), mu_b, kTol);
  EXPECT_NEAR(c.WeakenedFriction(mu_s, 10e-3, true), 0.5 * (mu_b + mu_k), kTol);
  EXPECT_NEAR(c.WeakenedFriction(mu_s, 10.0, true), mu_k, 1e-3);
  // breakaway_ratio = 1 (the default) is the continuous law.
  c.breakaway_ratio = 1.0;
  EXPECT_NEAR(c.WeakenedFriction(mu_s, 3e-3, true), c.WeakenedFriction(mu_s, 3e-3, false), kTol);
}

TEST(ContactFrictionTest, BreakawayBelowKineticIsRefusedNamingBothKeys) {
  ContactConfig c;
  c.kinetic_ratio = 0.6;
  c.breakaway_ratio = 0.5;
  const std::string what = InputErrorOf([&] { c.ValidateRules(); });
  EXPECT_NE(what.find("contact.breakaway_ratio = 0.5"), std::string::npos) << what;
  EXPECT_NE(what.find("contact.kinetic_ratio = 0.6"), std::string::npos) << what;
}

TEST(ContactFrictionTest, SlipMemoryWithoutVelocityWeakeningIsRefused) {
  ContactConfig c;
  c.slip_memory_um = 10.0;
  const std::string what = InputErrorOf([&] { c.ValidateRules(); });
  EXPECT_NE(what.find("contact.slip_memory_um = 10"), std::string::npos) << what;
  EXPECT_NE(what.find("contact.weakening_speed_mm_s > 0"), std::string::npos) << what;
  c.weakening_speed_mm_s = 1.0;
  EXPECT_NO_THROW(c.ValidateRules());
}

TEST(ContactFrictionTest, VelocityWeakeningRunsFromStaticAtRestToKineticWhenFast) {
  ContactConfig c;
  c.kinetic_ratio = 0.6;
  c.weakening_speed_mm_s = 2.0;
  const double mu_s = 1.2, mu_k = 0.72;
  EXPECT_NEAR(c.WeakenedFriction(mu_s, 0.0), mu_s, kTol);
  // Halfway between the two coefficients at the weakening speed (2 mm/s).
  EXPECT_NEAR(c.WeakenedFriction(mu_s, 2e-3), 0.5 * (mu_s + mu_k), kTol);
  // Within 0.1 % of kinetic three decades above it.
  EXPECT_NEAR(c.WeakenedFriction(mu_s, 2.0), mu_k, 1e-3 * mu_s);
  double prev = mu_s;
  for (double v = 1e-6; v < 1.0; v *= 1.5) {
    const double mu = c.WeakenedFriction(mu_s, v);
    EXPECT_LT(mu, prev) << "not decreasing at v = " << v;
    EXPECT_GT(mu, mu_k);
    prev = mu;
  }
}

TEST(ContactFrictionTest, PerPinSpreadAndWeakeningSpeedAreRangeChecked) {
  for (const auto& [key, fragment] : std::vector<std::pair<std::string, std::string>>{
           {"pin_friction_spread=0.5", "pin_friction_spread = 0.5"},
           {"pin_friction_spread=-0.1", "pin_friction_spread = -0.1"},
           {"weakening_speed_mm_s=-1", "weakening_speed_mm_s = -1"}}) {
    const std::string msg = InputErrorOf([&] { LoadConfig<ContactConfig>("", {key}); });
    EXPECT_NE(msg.find(fragment), std::string::npos) << key << ": '" << msg << "'";
  }
}

TEST_F(SkinTest, LatticeHas127PinsInSevenHexRings) {
  const PinLattice lat = PinLattice::Build(SkinConfig{});
  ASSERT_EQ(lat.size(), 127u);
  std::map<int, int> per_ring;
  for (const auto& p : lat.pins) per_ring[p.ring]++;
  EXPECT_EQ(per_ring[0], 1);
  for (int r = 1; r <= 6; ++r) EXPECT_EQ(per_ring[r], 6 * r) << "ring " << r;
  // Centre pin first, on the axis.
  EXPECT_EQ(lat.pins[0].ring, 0);
  EXPECT_NEAR(lat.pins[0].normal[0], 1.0, kTol);
}

TEST_F(SkinTest, NeighboursArePitchApartAlongTheDome) {
  SkinConfig cfg;
  const PinLattice lat = PinLattice::Build(cfg);
  // Hexagonal patch of radius r: 3 r (3 r + 1) edges.
  EXPECT_EQ(lat.neighbours.size(), static_cast<size_t>(3 * 6 * (3 * 6 + 1)));
  for (const auto& p : lat.pins) {
    const auto& n = p.normal;
    EXPECT_NEAR(n[0] * n[0] + n[1] * n[1] + n[2] * n[2], 1.0, kTol);
  }
  // The centre pin's neighbours sit one pitch of arc from the apex.
  for (const auto& e : lat.neighbours) {
    if (e[0] != 0) continue;
    EXPECT_NEAR(lat.pins[e[1]].polar_rad * cfg.radius_mm, cfg.pitch_mm, 1e-9);
  }
}

TEST_F(SkinTest, LatticeThatDoesNotFitIsRejected) {
  SkinConfig cfg;
  cfg.rings = 11;  // 33 mm of arc on a 20 mm dome is past the equator
  try {
    ValidateConfig(cfg);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("skin.rings = 11: lattice reaches"), std::string::npos) << e.what();
  }
}

TEST_F(SkinTest, MechanicsFollowMaterialFormulas) {
  SkinConfig cfg;
  const SkinMechanics m = SkinMechanics::From(cfg, 127);
  const double area = std::sqrt(3.0) / 2.0 * 9e-6;
  EXPECT_NEAR(m.k_normal_N_m, 100e3 * area / 0.02, 1e-9);
  EXPECT_NEAR(m.k_shear_N_m, 10e3 * area / 0.02, 1e-9);  // the gel's own shear modulus, 10 kPa
  EXPECT_NEAR(m.k_bend_N_m, 1e6 * 1e-9 / (12.0 * 0.75) / 9e-6, 1e-9);
  // Thickness enters the coupling as t^3 and the membrane stiffness as t.
  SkinConfig thick = cfg;
  thick.thickness_mm = 2.0;
  const SkinMechanics t2 = SkinMechanics::From(thick, 127);
  EXPECT_NEAR(t2.k_bend_N_m / m.k_bend_N_m, 8.0, 1e-9);
  EXPECT_NEAR(t2.membrane_N_m / m.membrane_N_m, 2.0, 1e-9);
}

TEST_F(SkinTest, GelShearModulusSetsTheShearColumnsAloneAndZeroMeansAThirdOfTheGelModulus) {
  SkinConfig cfg;
  EXPECT_DOUBLE_EQ(cfg.GelShearModulusPa(), 10e3);  // the default: the smooth shell's calibrated gel
  cfg.gel_shear_modulus_kpa = 0.0;
  EXPECT_DOUBLE_EQ(cfg.GelShearModulusPa(), 100e3 / 3.0);  // 0: the column's own modulus, incompressible
  const SkinMechanics stiff = SkinMechanics::From(cfg, 127);
  cfg.gel_shear_modulus_kpa = 5.0;
  const SkinMechanics soft = SkinMechanics::From(cfg, 127);
  const double area = std::sqrt(3.0) / 2.0 * 9e-6;
  EXPECT_NEAR(soft.k_shear_N_m, 5e3 * area / 0.02, 1e-9);
  EXPECT_DOUBLE_EQ(soft.k_normal_N_m, stiff.k_normal_N_m);  // the normal column keeps gel_modulus_kpa
  EXPECT_DOUBLE_EQ(soft.k_bend_N_m, stiff.k_bend_N_m);
  // The shell keeps its damping ratio on the softer columns: c = 2 zeta sqrt(n k_shear m).
  EXPECT_NEAR(soft.shell_damping_Ns_m / stiff.shell_damping_Ns_m, std::sqrt(5.0 / (100.0 / 3.0)), 1e-12);

  // The compiled smooth skin's shell carries all 127 columns in parallel.
  RailSceneSpec spec;
  spec.max_depth_m = 3.1e-3;
  spec.skin.gel_shear_modulus_kpa = 5.0;
  const CompiledModel m = CompiledModel::FromXml(BuildRailScene(spec).xml);
  const int joint = m.JointId("tactip/skin_shear_y");
  EXPECT_NEAR(m.raw()->jnt_stiffness[joint], 127.0 * soft.k_shear_N_m, 1e-9);

  cfg.gel_shear_modulus_kpa = -1.0;
  try {
    ValidateConfig(cfg);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("gel_shear_modulus_kpa = -1: must be >= 0"), std::string::npos) << e.what();
  }
}

TEST_F(SkinTest, RailSceneCompilesWithOnlyReachablePinsCollidable) {
  RailSceneSpec spec;
  spec.max_depth_m = 3.1e-3;
  const BuiltScene flat = BuildRailScene(spec);
  EXPECT_EQ(flat.n_pins, 127);
  EXPECT_GT(flat.n_collidable, 37);   // at least the pins inside the 3 mm contact
  EXPECT_LT(flat.n_collidable, 127);  // the outer rings cannot reach the plate
  const CompiledModel m = CompiledModel::FromXml(flat.xml);
  EXPECT_NO_THROW(m.GeomId(SkinNames{"tactip/"}.PinGeom(0)));
  EXPECT_THROW(m.GeomId(SkinNames{"tactip/"}.PinGeom(126)), ModelError);
  // A tighter curvature reaches fewer pins.
  spec.rail.stimulus = "curved20";
  const BuiltScene curved = BuildRailScene(spec);
  EXPECT_LT(curved.n_collidable, flat.n_collidable);
  EXPECT_NO_THROW(CompiledModel::FromXml(curved.xml));
}

TEST_F(SkinTest, UncoupledLatticeHasThreeSpringsPerPinAndNoCoupling) {
  RailSceneSpec spec;
  spec.max_depth_m = 3e-3;
  const CompiledModel shell = CompiledModel::FromXml(BuildRailScene(spec).xml);
  spec.skin.coupling = "none";
  const BuiltScene scene = BuildRailScene(spec);
  const CompiledModel brush = CompiledModel::FromXml(scene.xml);
  // Shell: 2 shear DOFs for the whole skin; uncoupled: 2 per pin instead.
  EXPECT_EQ(brush.nv() - shell.nv(), 2 * 127 - 2);
  EXPECT_NO_THROW(brush.JointId(SkinNames{"tactip/"}.PinShearJoint(5, 'y')));
  EXPECT_THROW(shell.JointId(SkinNames{"tactip/"}.PinShearJoint(5, 'y')), ModelError);
  EXPECT_EQ(scene.xml.find("<fixed"), std::string::npos) << "no bending tendons in the uncoupled lattice";
}

TEST_F(SkinTest, CulledPinsReallyCannotTouch) {
  // Pins without a contact geom must lie farther from the plate than the deepest press.
  SkinConfig skin;
  RailConfig rail;
  const PinLattice lat = PinLattice::Build(skin);
  const double depth = 3e-3;
  const auto coll = RailCollidablePins(skin, lat, rail, depth);
  ASSERT_LT(std::count(coll.begin(), coll.end(), true), static_cast<long>(lat.size()))
      << "premise: some pins are culled";
  for (const auto& p : lat.pins) {
    const double sag = skin.radius_mm * 1e-3 * (1.0 - p.normal[0]);  // apex-to-pin drop along the axis
    if (!coll[p.index]) {
      EXPECT_GT(sag, depth) << "pin " << p.index;
    }
  }
}

}  // namespace
}  // namespace tactip
