// Fingerprint skins (fingerprint-v1 raised rings, fingerprint-v2 wave): the ring layout of
// the pin lattice, the ridge mechanics derived from the materials, the shear damping
// floor of the membrane lattice, and the MJCF of a membrane-coupled skin.

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <sstream>
#include <cmath>
#include <functional>
#include <map>
#include <numbers>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "mujoco_warning_guard.h"
#include "models/membrane_elements.h"
#include "models/rail_rig.h"
#include "models/ridge_rocking.h"
#include "models/skin.h"
#include "sim/sim_config.h"
#include "sim/simulation.h"
#include "input_error.h"
#include "models/preset_skin.h"
#include "tests/long_experiment.h"

namespace tactip {
namespace {


/// Neighbour count of every pin.
std::vector<int> Degrees(const PinLattice& lat) {
  std::vector<int> d(lat.size(), 0);
  for (const auto& e : lat.neighbours) {
    ++d[e[0]];
    ++d[e[1]];
  }
  return d;
}

/// Ring-layout checks shared by both fingerprint presets.
void ExpectRingLayout(const SkinConfig& skin, int rings) {
  const PinLattice lat = PinLattice::Build(skin);
  // 1 + 6 (1 + 2 + ... + K) pins.
  ASSERT_EQ(lat.size(), static_cast<size_t>(1 + 3 * rings * (rings + 1)));
  std::map<int, std::vector<const PinGeometry*>> by_ring;
  for (const auto& p : lat.pins) by_ring[p.ring].push_back(&p);
  ASSERT_EQ(by_ring.size(), static_cast<size_t>(rings + 1));
  for (int k = 0; k <= rings; ++k) {
    const auto& ring = by_ring[k];
    ASSERT_EQ(ring.size(), static_cast<size_t>(k == 0 ? 1 : skin.pins_per_ring * k)) << "ring " << k;
    for (size_t j = 0; j < ring.size(); ++j) {
      const PinGeometry& p = *ring[j];
      // Arc radius along the dome: k ridge steps.
      EXPECT_NEAR(p.polar_rad * skin.radius_mm, k * skin.ridge_spacing_mm, 1e-9) << "pin " << p.index;
      const auto& n = p.normal;
      EXPECT_NEAR(n[0] * n[0] + n[1] * n[1] + n[2] * n[2], 1.0, 1e-12);
      // Equally spaced in azimuth, in azimuth order.
      if (k > 0) {
        EXPECT_NEAR(p.azimuth_rad, 2.0 * std::numbers::pi * static_cast<double>(j) / ring.size(), 1e-9)
            << "pin " << p.index;
      }
    }
  }
  // Pins are ordered by ring and indexed by position.
  for (size_t i = 0; i < lat.size(); ++i) {
    EXPECT_EQ(lat.pins[i].index, static_cast<int>(i));
    if (i > 0) {
      EXPECT_LE(lat.pins[i - 1].ring, lat.pins[i].ring);
    }
  }
  // Edges: i < j, no duplicates, only within a ring or between adjacent rings, and
  // never longer than 1.5 ridge steps in the plane of the layout.
  std::set<std::array<int, 2>> seen;
  for (const auto& e : lat.neighbours) {
    EXPECT_LT(e[0], e[1]);
    EXPECT_TRUE(seen.insert(e).second) << "duplicate edge " << e[0] << "-" << e[1];
    const PinGeometry& a = lat.pins[e[0]];
    const PinGeometry& b = lat.pins[e[1]];
    EXPECT_LE(std::abs(a.ring - b.ring), 1) << "edge " << e[0] << "-" << e[1];
    const double ra = a.polar_rad * skin.radius_mm, rb = b.polar_rad * skin.radius_mm;
    const double d = std::hypot(ra * std::cos(a.azimuth_rad) - rb * std::cos(b.azimuth_rad),
                                ra * std::sin(a.azimuth_rad) - rb * std::sin(b.azimuth_rad));
    EXPECT_LE(d, 1.5 * skin.ridge_spacing_mm) << "edge " << e[0] << "-" << e[1];
  }
  const std::vector<int> degree = Degrees(lat);
  for (size_t i = 0; i < lat.size(); ++i) EXPECT_GE(degree[i], 2) << "pin " << i;
  EXPECT_EQ(degree[0], skin.pins_per_ring) << "the centre pin links to every pin of ring 1";
  // Every pin beyond the centre links inwards (the band between two rings is meshed).
  std::vector<bool> inward(lat.size(), false);
  for (const auto& e : lat.neighbours) {
    if (lat.pins[e[1]].ring == lat.pins[e[0]].ring + 1) inward[e[1]] = true;
  }
  for (size_t i = 1; i < lat.size(); ++i) EXPECT_TRUE(inward[i]) << "pin " << i << " has no inner neighbour";
  // The mechanics see the lattice's real maximum degree.
  EXPECT_EQ(SkinMechanics::From(skin, lat).max_degree, *std::max_element(degree.begin(), degree.end()));
}

TEST(FingerprintLatticeTest, V2PresetHas127PinsOnSixRingsThreeMillimetresApart) {
  const SkinConfig v2 = PresetSkin("fingerprint-v2");
  EXPECT_EQ(v2.pattern, "fingerprint-v2");
  EXPECT_EQ(v2.coupling, "membrane");
  ExpectRingLayout(v2, 6);  // 1 + 6 + 12 + ... + 36 = 127
}

TEST(FingerprintLatticeTest, V1PresetHas91PinsOnFiveRingsFourMillimetresApart) {
  const SkinConfig v1 = PresetSkin("fingerprint-v1");
  EXPECT_EQ(v1.pattern, "fingerprint-v1");
  EXPECT_EQ(v1.ridge_shape, "square");
  ExpectRingLayout(v1, 5);  // 1 + 6 + 12 + ... + 30 = 91
}

TEST(FingerprintLatticeTest, RingCountIsTheLargestStepWithinThePatternRadius) {
  SkinConfig s = PresetSkin("fingerprint-v2");
  s.pattern_radius_mm = 17.99;  // ring 6 at 18 mm no longer fits
  EXPECT_EQ(PinLattice::Build(s).size(), 91u);
  s.pattern_radius_mm = 18.0;  // exactly on the ring
  EXPECT_EQ(PinLattice::Build(s).size(), 127u);
  s.pins_per_ring = 8;
  EXPECT_EQ(PinLattice::Build(s).size(), static_cast<size_t>(1 + 8 * 21));
}

TEST(FingerprintLatticeTest, UnknownPresetIsAnInputErrorListingTheKnownSkins) {
  const std::string msg = InputErrorOf([] { SkinPreset("fingerprint-v3"); });
  EXPECT_NE(msg.find("fingerprint-v3"), std::string::npos) << msg;
  EXPECT_NE(msg.find("smooth, fingerprint-v1, fingerprint-v2"), std::string::npos) << msg;
  EXPECT_EQ(PresetSkin("smooth").pattern, "smooth");
  EXPECT_EQ(PresetSkin("smooth").coupling, "shell");
}

// ---- Mechanics --------------------------------------------------------------------

TEST(FingerprintMechanicsTest, ThickerSkinStiffensRidgesAndCouplingAndShiftsComplianceOutOfTheRidge) {
  for (const char* name : {"fingerprint-v1", "fingerprint-v2"}) {
    SCOPED_TRACE(name);
    SkinConfig thin = PresetSkin(name);
    SkinConfig thick = thin;
    thick.thickness_mm = 2.0 * thin.thickness_mm;
    const SkinMechanics a = SkinMechanics::From(thin, 127);
    const SkinMechanics b = SkinMechanics::From(thick, 127);
    EXPECT_GT(b.k_rock_N_m, a.k_rock_N_m);
    EXPECT_GT(b.k_couple_N_m, a.k_couple_N_m);
    EXPECT_GT(b.k_link_N_m, a.k_link_N_m);
    // Share of the link-plus-two-ridges compliance that sits in the ridges.
    auto ridge_share = [](const SkinMechanics& m) {
      return (2.0 / m.k_rock_N_m) / (1.0 / m.k_link_N_m + 2.0 / m.k_rock_N_m);
    };
    EXPECT_LT(ridge_share(b), ridge_share(a));
    // The gel under the pin does not depend on the skin.
    EXPECT_DOUBLE_EQ(b.k_shear_N_m, a.k_shear_N_m);
  }
}

TEST(FingerprintMechanicsTest, WiderRidgeSpacingGivesEachPinALargerGelCell) {
  SkinConfig a = PresetSkin("fingerprint-v2");
  SkinConfig b = a;
  b.ridge_spacing_mm = 4.5;
  const SkinMechanics ma = SkinMechanics::From(a, 127);
  const SkinMechanics mb = SkinMechanics::From(b, 127);
  // Cell = one ring step by the arc per pin (2 pi s / pins_per_ring): area ~ s^2.
  EXPECT_NEAR(ma.cell_area_m2, 3e-3 * 2.0 * std::numbers::pi * 3e-3 / 6.0, 1e-15);
  EXPECT_NEAR(mb.k_shear_N_m / ma.k_shear_N_m, (4.5 / 3.0) * (4.5 / 3.0), 1e-12);
  EXPECT_NEAR(mb.k_normal_N_m / ma.k_normal_N_m, (4.5 / 3.0) * (4.5 / 3.0), 1e-12);
  // The gel column's shear and normal stiffness share its cell and depth: their ratio is G / E.
  EXPECT_NEAR(ma.k_shear_N_m / ma.k_normal_N_m, a.GelShearModulusPa() / (a.gel_modulus_kpa * 1e3), 1e-12);
}

TEST(FingerprintMechanicsTest, RockingStiffnessFallsWithTheSquareOfTheLever) {
  SkinConfig low = PresetSkin("fingerprint-v1");  // square ridge: lever = height
  SkinConfig high = low;
  high.ridge_height_mm = 3.0;
  const SkinMechanics ml = SkinMechanics::From(low, 91);
  const SkinMechanics mh = SkinMechanics::From(high, 91);
  ASSERT_GT(mh.k_rock_N_m, 0.0);
  EXPECT_NEAR(ml.k_rock_N_m / mh.k_rock_N_m, (3.0 / 2.0) * (3.0 / 2.0), 1e-12);
  // A sine wave rocks about mid-height: half the lever, four times the stiffness.
  SkinConfig sine = low;
  sine.ridge_shape = "sine";
  const SkinMechanics ms = SkinMechanics::From(sine, 91);
  EXPECT_NEAR(ms.k_rock_N_m / ml.k_rock_N_m, 4.0, 1e-12);
}

// skin.ridge_rocking = half-space: the gel's share of a ridge's rocking stiffness is a rigid
// strip of half-width c = w / 2 tilted by theta on an incompressible half-space, whose pressure
// p(x) = E* theta x / (2 sqrt(c^2 - x^2)), E* = 4 E / 3, has the moment pi E* c^2 theta / 4 per
// unit length; here integrated numerically (x = c sin phi removes the edge singularities).
TEST(FingerprintMechanicsTest, HalfSpaceRockingIsTheMomentOfATiltedStripsPressure) {
  const double E = 1e5, b = 3e-3, w = 2e-3, c = 0.5 * w, theta = 1e-3, e_star = 4.0 / 3.0 * E;
  // p(x) x dx = E* theta c^2 sin^2(phi) / 2 dphi over phi in (-pi/2, pi/2): midpoint rule.
  const int n = 4000;
  double moment = 0.0;
  for (int k = 0; k < n; ++k) {
    const double phi = -0.5 * std::numbers::pi + (k + 0.5) * std::numbers::pi / n;
    moment += 0.5 * e_star * theta * c * c * std::sin(phi) * std::sin(phi) * std::numbers::pi / n;
  }
  EXPECT_NEAR(RockingGelStiffness("half-space", E, 0.02, b, w), b * moment / theta, 1e-9 * b * moment / theta);
  // Winkler: each column (E / h) dx at x carries (E / h) theta x, moment (E / h) theta w^3 / 12.
  double columns = 0.0;
  for (int k = 0; k < n; ++k) {
    const double x = -c + (k + 0.5) * w / n;
    columns += E / 0.02 * x * x * w / n;
  }
  EXPECT_NEAR(RockingGelStiffness("winkler", E, 0.02, b, w), b * columns, 1e-6 * b * columns);
  EXPECT_THROW(RockingGelStiffness("halfspace", E, 0.02, b, w), std::invalid_argument);
}

// The presets' ridges on either gel model: the figures the key's help and the table in
// docs/fingerprint-skins.md ('Ridge rocking') quote, and the hinges, tip and coupling built on
// them as before.
TEST(FingerprintMechanicsTest, HalfSpaceRockingStiffensThePresetsRidgesAsDocumented) {
  struct Quoted {
    double k_rock, k_tip, k_couple;
  };
  const std::map<std::pair<std::string, std::string>, Quoted> quoted = {
      {{"fingerprint-v1", "winkler"}, {9.31, 3.49, 4.53}},
      {{"fingerprint-v1", "half-space"}, {115.0, 5.33, 43.3}},
      {{"fingerprint-v2", "winkler"}, {191.0, 3.09, 74.7}},
      {{"fingerprint-v2", "half-space"}, {371.0, 3.12, 121.0}}};
  for (const auto& [key, q] : quoted) {
    SCOPED_TRACE(key.first + " " + key.second);
    SkinConfig s = PresetSkin(key.first);
    s.ridge_rocking = key.second;
    ValidateConfig(s);
    const SkinMechanics m = SkinMechanics::From(s, 127);
    EXPECT_NEAR(m.k_rock_N_m, q.k_rock, 0.006 * q.k_rock);
    EXPECT_NEAR(m.k_tip_N_m, q.k_tip, 0.006 * q.k_tip);
    EXPECT_NEAR(m.k_couple_N_m, q.k_couple, 0.006 * q.k_couple);
    EXPECT_NEAR(m.k_couple_N_m, 1.0 / (1.0 / m.k_link_N_m + 2.0 / m.k_rock_N_m), 1e-9 * m.k_couple_N_m);
  }
  SkinConfig smooth = PresetSkin("smooth");
  smooth.ridge_rocking = "half-space";
  EXPECT_EQ(SkinMechanics::From(smooth, 127).k_rock_N_m, 0.0);
}

TEST(FingerprintMechanicsTest, TipAndCouplingAreSeriesCombinations) {
  for (const char* name : {"fingerprint-v1", "fingerprint-v2"}) {
    SCOPED_TRACE(name);
    const SkinConfig s = PresetSkin(name);
    const SkinMechanics m = SkinMechanics::From(s, 127);
    ASSERT_GT(m.k_rock_N_m, 0.0);
    EXPECT_NEAR(m.k_tip_N_m, 1.0 / (1.0 / m.k_shear_N_m + 1.0 / m.k_rock_N_m), 1e-9 * m.k_tip_N_m);
    EXPECT_LT(m.k_tip_N_m, std::min(m.k_shear_N_m, m.k_rock_N_m));
    EXPECT_NEAR(m.k_link_N_m, std::sqrt(3.0) / 2.0 * s.skin_modulus_mpa * 1e6 * s.thickness_mm * 1e-3, 1e-9);
    EXPECT_NEAR(m.k_couple_N_m, 1.0 / (1.0 / m.k_link_N_m + 2.0 / m.k_rock_N_m), 1e-9 * m.k_couple_N_m);
    // The physical shear damping is set on the tip stiffness.
    EXPECT_NEAR(m.tip_damping_Ns_m, 2.0 * s.shear_damping_ratio * std::sqrt(m.k_tip_N_m * s.pin_mass_g * 1e-3),
                1e-12);
  }
}

TEST(FingerprintMechanicsTest, SmoothSkinHasNoRidges) {
  SkinConfig s;  // smooth, shell
  s.coupling = "membrane";
  const SkinMechanics m = SkinMechanics::From(s, 127);
  EXPECT_EQ(m.k_rock_N_m, 0.0);
  EXPECT_EQ(m.k_tip_N_m, m.k_shear_N_m);
  EXPECT_EQ(m.k_couple_N_m, m.k_link_N_m);
  EXPECT_EQ(m.marker_rock_factor, 0.0);
  // Ridge keys are ignored without a fingerprint pattern.
  SkinConfig tall = s;
  tall.ridge_height_mm = 5.0;
  tall.ridge_spacing_mm = 7.0;
  EXPECT_EQ(SkinMechanics::From(tall, 127).k_shear_N_m, m.k_shear_N_m);
  EXPECT_EQ(tall.OuterRadiusMm(), s.radius_mm);
}

TEST(FingerprintMechanicsTest, MarkerRockFactorPivotsV1MarkersButNotV2) {
  const SkinConfig v1 = PresetSkin("fingerprint-v1");
  const SkinConfig v2 = PresetSkin("fingerprint-v2");
  // v1: the inner pin end sits a skin thickness below the pivot at the ridge root.
  EXPECT_NEAR(SkinMechanics::From(v1, 91).marker_rock_factor, 1.0 + v1.thickness_mm / v1.ridge_height_mm, 1e-12);
  EXPECT_NEAR(SkinMechanics::From(v1, 91).marker_rock_factor, 1.25, 1e-12);
  EXPECT_EQ(SkinMechanics::From(v2, 127).marker_rock_factor, 1.0);
  // Geometry: the ridges raise the contact surface; contact patches fit between rings.
  EXPECT_DOUBLE_EQ(v1.OuterRadiusMm(), v1.radius_mm + v1.ridge_height_mm);
  EXPECT_DOUBLE_EQ(v2.ContactRadiusMm(), std::min(v2.contact_radius_mm, 0.5 * v2.ridge_spacing_mm));
  SkinConfig narrow = v2;
  narrow.ridge_spacing_mm = 2.0;
  EXPECT_DOUBLE_EQ(narrow.ContactRadiusMm(), 1.0);
}

// ---- Shear damping floor -------------------------------------------------------------

TEST(FingerprintMechanicsTest, TipDampingIsPhysicalWhereStableAndRaisedJustEnoughElsewhere) {
  const SkinConfig v2 = PresetSkin("fingerprint-v2");
  const SkinMechanics m = SkinMechanics::From(v2, PinLattice::Build(v2));
  const double w = m.StiffestShearOmega();
  const double mass = m.pin_mass_kg;
  auto zeta_of = [&](double c) { return c / (2.0 * mass * w); };
  ASSERT_GT(w, 0.0);

  // A small step: the physical damping is already stable, so it is kept.
  const double dt_small = 0.2 / w;
  ASSERT_GE(MaxStableTimestep(w, zeta_of(m.tip_damping_Ns_m)), 1.2 * dt_small);
  EXPECT_EQ(m.TipDamping(dt_small), m.tip_damping_Ns_m);

  // The default 2 ms step is beyond the physical damping's limit: the damping is raised
  // until the mode is stable with the documented 20 % margin.
  const double dt = 2e-3;
  ASSERT_LT(MaxStableTimestep(w, zeta_of(m.tip_damping_Ns_m)), dt) << "premise: 2 ms needs the floor";
  const double c = m.TipDamping(dt);
  EXPECT_GT(c, m.tip_damping_Ns_m);
  EXPECT_GE(MaxStableTimestep(w, zeta_of(c)), dt);
  EXPECT_NEAR(MaxStableTimestep(w, zeta_of(c)), 1.2 * dt, 1e-9 * dt);  // not more than needed
  // A larger step needs more damping, and gets it.
  const double c4 = m.TipDamping(4e-3);
  EXPECT_GT(c4, c);
  EXPECT_GE(MaxStableTimestep(w, zeta_of(c4)), 4e-3);
}

TEST(FingerprintMechanicsTest, StiffestShearModeCountsEveryNeighbourCoupling) {
  const SkinConfig v2 = PresetSkin("fingerprint-v2");
  const PinLattice lat = PinLattice::Build(v2);
  const SkinMechanics m = SkinMechanics::From(v2, lat);
  // The stiffest pin: an outer-ring pin, which also carries its share of the clamped rim.
  ASSERT_GT(m.k_rim_pin_N_m, 0.0) << "premise: the default rim is clamped";
  EXPECT_NEAR(m.StiffestShearOmega(),
              std::sqrt((m.TipStiffness(m.rim_ring) + 2.0 * m.max_degree * m.k_couple_N_m) / m.pin_mass_kg), 1e-9);
  SkinMechanics fewer = m;
  fewer.max_degree = m.max_degree - 1;
  EXPECT_LT(fewer.StiffestShearOmega(), m.StiffestShearOmega());
}

// ---- MJCF of a membrane lattice -------------------------------------------------------

/// The pin bodies of a skin part, by pin index.
std::map<int, const mjcf::Element*> PinBodies(const SkinPart& part) {
  std::map<int, const mjcf::Element*> out;
  for (const auto& child : part.body.children()) {
    if (child.tag() != "body") continue;
    const std::string name = child.Get("name");
    out[std::stoi(name.substr(3))] = &child;  // "pin<i>"
  }
  return out;
}

// Compiling a scene runs MuJoCo (its setup pass on a scratch mjData): no warning allowed.
class FingerprintSkinPartTest : public testing::MujocoWarningGuard {};

// Every pin of a membrane lattice shears on the gel (the skin beyond the contact is
// dragged along by the membrane); only pins that can touch the plate move normally.
TEST_F(FingerprintSkinPartTest, MembraneLatticeGivesShearDofsToEveryPinAndNormalDofsToCollidablePins) {
  const SkinConfig v2 = PresetSkin("fingerprint-v2");
  const PinLattice lat = PinLattice::Build(v2);
  RailConfig rail;
  rail.stimulus = "acrylic";
  const std::vector<bool> coll = RailCollidablePins(v2, lat, rail, 3.1e-3);
  const int n_coll = static_cast<int>(std::count(coll.begin(), coll.end(), true));
  ASSERT_GT(n_coll, 0);
  ASSERT_LT(n_coll, static_cast<int>(lat.size())) << "premise: some pins cannot reach the plate";
  const double dt = 2e-3;
  const SkinPart part = BuildSkin(v2, ContactConfig{}, lat, coll, dt);
  const SkinMechanics m = SkinMechanics::From(v2, lat);
  EXPECT_EQ(part.n_collidable, n_coll);

  const auto bodies = PinBodies(part);
  ASSERT_EQ(bodies.size(), lat.size());
  std::set<std::string> moving_joints;
  for (const auto& [i, body] : bodies) {
    std::vector<std::string> joints;
    int geoms = 0, sites = 0;
    for (const auto& c : body->children()) {
      if (c.tag() == "joint") joints.push_back(c.Get("name"));
      if (c.tag() == "geom") ++geoms;
      if (c.tag() == "site") ++sites;
    }
    EXPECT_EQ(sites, 2) << "pin " << i << ": inner marker and outer contact point";
    const std::vector<std::string> shear{SkinNames{}.PinShearJoint(i, 'y'), SkinNames{}.PinShearJoint(i, 'z')};
    if (coll[i]) {
      EXPECT_EQ(geoms, 1) << "pin " << i;
      EXPECT_EQ(joints, (std::vector<std::string>{SkinNames{}.PinJoint(i), shear[0], shear[1]})) << "pin " << i;
    } else {
      EXPECT_EQ(geoms, 0) << "pin " << i;
      EXPECT_EQ(joints, shear) << "non-collidable pin " << i;
    }
    for (const auto& c : body->children()) {
      if (c.tag() != "joint" || c.Get("name") == SkinNames{}.PinJoint(i)) continue;
      EXPECT_DOUBLE_EQ(std::stod(c.Get("stiffness")), m.TipStiffness(lat.pins[i].ring)) << c.Get("name");
      EXPECT_DOUBLE_EQ(std::stod(c.Get("damping")), m.TipDamping(dt)) << c.Get("name");
    }
    moving_joints.insert(joints.begin(), joints.end());
  }
  // Tendons list only joints that exist.
  int membrane = 0, bend = 0;
  for (const auto& t : part.tendons) {
    const std::string name = t.Get("name");
    if (name.rfind("membrane_", 0) == 0) {
      ++membrane;
      EXPECT_DOUBLE_EQ(std::stod(t.Get("stiffness")), m.k_couple_N_m) << name;
    } else if (name.rfind("bend_", 0) == 0) {
      ++bend;
    } else {
      ADD_FAILURE() << "unexpected tendon " << name;
    }
    ASSERT_FALSE(t.children().empty()) << name;
    for (const auto& j : t.children()) {
      EXPECT_EQ(moving_joints.count(j.Get("joint")), 1u) << name << " references " << j.Get("joint");
    }
  }
  // Membrane springs on every edge; bending springs where at least one end moves normally.
  int live_edges = 0;
  for (const auto& e : lat.neighbours) live_edges += (coll[e[0]] || coll[e[1]]) ? 1 : 0;
  EXPECT_EQ(membrane, 2 * static_cast<int>(lat.neighbours.size()));
  EXPECT_EQ(bend, live_edges);
}

/// Adds each tendon's stiffness k c c^T to K, for the tendons `use` accepts by name, over
/// their joints numbered by `dof`.
void AddTendonStiffness(Eigen::MatrixXd& K, const SkinPart& part, const std::map<std::string, int>& dof,
                        const std::function<bool(const std::string&)>& use) {
  for (const auto& t : part.tendons) {
    if (!use(t.Get("name"))) continue;
    const double k = std::stod(t.Get("stiffness"));
    for (const auto& ja : t.children()) {
      for (const auto& jb : t.children()) {
        K(dof.at(ja.Get("joint")), dof.at(jb.Get("joint"))) += k * std::stod(ja.Get("coef")) * std::stod(jb.Get("coef"));
      }
    }
  }
}

/// The lattice's shear stiffness as built: each pin's own spring on both shear DOFs (in order
/// pin, axis) plus k c c^T over the joints of every membrane tendon.
Eigen::MatrixXd MembraneShearStiffness(const SkinPart& part, const PinLattice& lattice, const SkinMechanics& m) {
  const int n = static_cast<int>(lattice.size());
  std::map<std::string, int> dof;
  for (int i = 0; i < n; ++i) {
    dof[SkinNames{}.PinShearJoint(i, 'y')] = 2 * i;
    dof[SkinNames{}.PinShearJoint(i, 'z')] = 2 * i + 1;
  }
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  for (const auto& pin : lattice.pins) {
    K(2 * pin.index, 2 * pin.index) = K(2 * pin.index + 1, 2 * pin.index + 1) = m.TipStiffness(pin.ring);
  }
  AddTendonStiffness(K, part, dof, [](const std::string& name) { return name.rfind("membrane_", 0) == 0; });
  return K;
}

/// The v2 preset with central membrane links, every pin collidable, at 0.25 ms.
struct CentralV2 {
  SkinConfig skin = [] {
    SkinConfig s = PresetSkin("fingerprint-v2");
    s.membrane_links = "central";
    return s;
  }();
  PinLattice lattice = PinLattice::Build(skin);
  SkinPart part = BuildSkin(skin, ContactConfig{}, lattice, std::vector<bool>(lattice.size(), true), 2.5e-4);
  SkinMechanics mech = SkinMechanics::From(skin, lattice);
};

/// A pin body's position (y, z) in the skin frame, from its MJCF.
std::array<double, 2> PinBodyYz(const SkinPart& part, int pin) {
  const mjcf::Element* body = PinBodies(part).at(pin);
  std::istringstream pos(body->Get("pos"));
  double x = 0, y = 0, z = 0;
  pos >> x >> y >> z;
  return {y, z};
}

// skin.membrane_links = central: one spring per link, along the line between its two pin
// bodies, taking the ridges' rocking by the link's radial share.
TEST_F(FingerprintSkinPartTest, CentralLinksPullAlongThemselvesWithTheRidgesByTheirRadialShare) {
  const CentralV2 v2;
  const SkinMechanics& m = v2.mech;
  ASSERT_TRUE(m.central_links);
  ASSERT_GT(m.k_rock_N_m, 0.0);
  std::map<std::string, const mjcf::Element*> by_name;
  for (const auto& t : v2.part.tendons) by_name[t.Get("name")] = &t;
  int radial = 0, hoop = 0, slanted = 0, membrane = 0;
  for (const auto& t : v2.part.tendons) membrane += t.Get("name").rfind("membrane_", 0) == 0 ? 1 : 0;
  EXPECT_EQ(membrane, static_cast<int>(v2.lattice.neighbours.size())) << "one tendon per link";
  for (const auto& e : v2.lattice.neighbours) {
    const auto it = by_name.find(fmt::format("membrane_{}_{}", e[0], e[1]));
    ASSERT_NE(it, by_name.end()) << "edge " << e[0] << "-" << e[1];
    const auto& joints = it->second->children();
    ASSERT_EQ(joints.size(), 4u);
    const SkinNames names;
    EXPECT_EQ(joints[0].Get("joint"), names.PinShearJoint(e[0], 'y'));
    EXPECT_EQ(joints[1].Get("joint"), names.PinShearJoint(e[0], 'z'));
    EXPECT_EQ(joints[2].Get("joint"), names.PinShearJoint(e[1], 'y'));
    EXPECT_EQ(joints[3].Get("joint"), names.PinShearJoint(e[1], 'z'));
    const double cy = std::stod(joints[0].Get("coef")), cz = std::stod(joints[1].Get("coef"));
    EXPECT_NEAR(std::stod(joints[2].Get("coef")), -cy, 1e-15);
    EXPECT_NEAR(std::stod(joints[3].Get("coef")), -cz, 1e-15);
    EXPECT_NEAR(std::hypot(cy, cz), 1.0, 1e-12);
    // Along the line between the two pin bodies as built: moving a pin across it does not
    // stretch the link.
    const auto p0 = PinBodyYz(v2.part, e[0]), p1 = PinBodyYz(v2.part, e[1]);
    const double ly = p1[0] - p0[0], lz = p1[1] - p0[1];
    EXPECT_NEAR(cy * lz - cz * ly, 0.0, 1e-9 * std::hypot(ly, lz)) << "edge " << e[0] << "-" << e[1];
    const double k = std::stod(it->second->Get("stiffness"));
    const PinGeometry& a = v2.lattice.pins[e[0]];
    const PinGeometry& b = v2.lattice.pins[e[1]];
    if (a.ring == 0) {
      // From the apex: straight out, through both ridges, as the isotropic coupling.
      EXPECT_NEAR(k, m.k_couple_N_m, 1e-9 * k);
      ++radial;
    } else if (a.ring == b.ring) {
      // Neighbours on one ring: along the ridge, which does not rock along itself.
      EXPECT_NEAR(k, m.k_link_N_m, 1e-9 * k);
      ++hoop;
    } else {
      // Between rings: k_couple where the two pins share an azimuth, stiffer where slanted.
      EXPECT_GE(k, m.k_couple_N_m * (1.0 - 1e-9));
      EXPECT_LT(k, m.k_link_N_m);
      slanted += k > m.k_couple_N_m * (1.0 + 1e-6) ? 1 : 0;
    }
  }
  EXPECT_EQ(radial, v2.skin.pins_per_ring);
  EXPECT_GT(hoop, 0);
  EXPECT_GT(slanted, 0);
}

// The damping floor's bound on the stiffest shear mode (Gershgorin: the widest row of the
// shear stiffness matrix, each link's entries added by magnitude) lies above the matrix's
// largest eigenvalue, and much closer to it than every link taken at k_link.
TEST_F(FingerprintSkinPartTest, CentralLinksStiffestShearBoundCoversTheLargestEigenvalue) {
  const CentralV2 v2;
  const SkinMechanics& m = v2.mech;
  const Eigen::MatrixXd K = MembraneShearStiffness(v2.part, v2.lattice, m);
  const double largest = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(K).eigenvalues().maxCoeff();
  const double widest_row = K.cwiseAbs().rowwise().sum().maxCoeff();
  const double bound = m.StiffestShearOmega() * m.StiffestShearOmega() * m.pin_mass_kg;
  // The bound adds every link's entries by magnitude, so it lies at or above the matrix's own
  // widest row, where entries of different links can cancel.
  EXPECT_GE(bound, widest_row * (1.0 - 1e-12));
  EXPECT_GE(widest_row, largest);
  EXPECT_LT(bound, 1.6 * largest) << "largest eigenvalue " << largest;
  const double every_link_at_k_link =
      m.TipStiffness(m.rim_ring) + m.max_degree * (1.0 + std::numbers::sqrt2) * m.k_link_N_m;
  EXPECT_GT(every_link_at_k_link, 3.0 * largest);
}

/// The v2 preset with the orthotropic membrane, every pin collidable, at 0.5 ms.
struct OrthotropicV2 {
  SkinConfig skin = [] {
    SkinConfig s = PresetSkin("fingerprint-v2");
    s.membrane_links = "orthotropic";
    return s;
  }();
  PinLattice lattice = PinLattice::Build(skin);
  SkinPart part = BuildSkin(skin, ContactConfig{}, lattice, std::vector<bool>(lattice.size(), true), 5e-4);
  SkinMechanics mech = SkinMechanics::From(skin, lattice);
};

// skin.membrane_links = orthotropic: one tendon per stiffness mode of each (weighted) triangle over its
// three pins' six shear joints, no pair links; the damping floor's Gershgorin bound covers the
// assembled stiffness's largest eigenvalue.
TEST_F(FingerprintSkinPartTest, OrthotropicMembraneIsThreeTendonsPerTriangleUnderTheStiffnessBound) {
  const OrthotropicV2 v2;
  const SkinMechanics& m = v2.mech;
  ASSERT_TRUE(m.orthotropic_links);
  ASSERT_FALSE(m.central_links);
  int modes = 0;
  for (const auto& t : v2.part.tendons) {
    const std::string name = t.Get("name");
    if (name.rfind("membrane_", 0) != 0) continue;
    EXPECT_EQ(name.rfind("membrane_mode_", 0), 0u) << name;
    EXPECT_EQ(t.children().size(), 6u) << name;
    EXPECT_GT(std::stod(t.Get("stiffness")), 0.0) << name;
    ++modes;
  }
  EXPECT_EQ(modes, static_cast<int>(3 * SymmetricRingTriangles(v2.lattice).size()));
  const Eigen::MatrixXd K = MembraneShearStiffness(v2.part, v2.lattice, m);
  const double largest = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(K).eigenvalues().maxCoeff();
  const double bound = m.StiffestShearOmega() * m.StiffestShearOmega() * m.pin_mass_kg;
  EXPECT_GE(bound, K.cwiseAbs().rowwise().sum().maxCoeff() * (1.0 - 1e-9));
  EXPECT_GE(bound, largest);
  EXPECT_LT(bound, 3.0 * largest) << "largest eigenvalue " << largest;
}

/// The v2 preset with dome springs (skin.normal_spring = dome) and `sets` applied (keys
/// without the "skin." prefix), every pin collidable, at step `dt`.
struct DomeV2 {
  SkinConfig skin;
  PinLattice lattice;
  SkinMechanics mech;
  SkinPart part;

  explicit DomeV2(double dt = 5e-4, const FlatConfig& sets = {})
      : skin(Skin(sets)), lattice(PinLattice::Build(skin)), mech(SkinMechanics::From(skin, lattice)),
        part(BuildSkin(skin, ContactConfig{}, lattice, std::vector<bool>(lattice.size(), true), dt)) {}
  static SkinConfig Skin(const FlatConfig& sets) {
    SkinConfig s = PresetSkin("fingerprint-v2");
    s.normal_spring = "dome";
    ApplyFlat(s, sets);
    ValidateConfig(s);
    return s;
  }
};

bool IsDomeSpring(const std::string& tendon) { return tendon.find("_dome_spring") != std::string::npos; }

// Each pin with a normal DOF has its gel spring as one fixed tendon, L = q_n + (n_y q_y +
// n_z q_z) / n_x at k_n, and its normal joint no spring of its own; the default axial
// springs are the normal joints' own.
TEST_F(FingerprintSkinPartTest, DomeSpringsAreOneTendonPerPinOverItsNormalAndShearJoints) {
  const DomeV2 v2;
  const SkinNames names;
  std::map<std::string, const mjcf::Element*> springs;
  for (const auto& t : v2.part.tendons) {
    if (IsDomeSpring(t.Get("name"))) springs[t.Get("name")] = &t;
  }
  ASSERT_EQ(springs.size(), v2.lattice.size());
  for (const PinGeometry& pin : v2.lattice.pins) {
    SCOPED_TRACE("pin " + std::to_string(pin.index));
    const mjcf::Element& t = *springs.at(names.PinDomeSpring(pin.index));
    EXPECT_DOUBLE_EQ(std::stod(t.Get("stiffness")), v2.mech.k_normal_N_m);
    std::map<std::string, double> coef;
    for (const auto& j : t.children()) coef[j.Get("joint")] = std::stod(j.Get("coef"));
    ASSERT_EQ(coef.size(), 3u);
    const auto& n = pin.normal;
    EXPECT_DOUBLE_EQ(coef.at(names.PinJoint(pin.index)), 1.0);
    EXPECT_NEAR(coef.at(names.PinShearJoint(pin.index, 'y')), n[1] / n[0], 1e-6);
    EXPECT_NEAR(coef.at(names.PinShearJoint(pin.index, 'z')), n[2] / n[0], 1e-6);
  }
  for (const auto& [i, body] : PinBodies(v2.part)) {
    for (const auto& c : body->children()) {
      if (c.tag() == "joint" && c.Get("name") == names.PinJoint(i)) {
        EXPECT_EQ(std::stod(c.Get("stiffness")), 0.0);
      }
    }
  }
  // Pins without a normal DOF (a membrane lattice's pins that cannot touch) get no spring.
  std::vector<bool> inner(v2.lattice.size(), false);
  for (const auto& pin : v2.lattice.pins) inner[pin.index] = pin.ring <= 1;
  const SkinPart part = BuildSkin(v2.skin, ContactConfig{}, v2.lattice, inner, 5e-4);
  int with_spring = 0;
  for (const auto& t : part.tendons) with_spring += IsDomeSpring(t.Get("name")) ? 1 : 0;
  EXPECT_EQ(with_spring, 1 + v2.skin.pins_per_ring);
  SkinConfig axial = v2.skin;
  axial.normal_spring = "axial";
  const SkinPart plain = BuildSkin(axial, ContactConfig{}, v2.lattice, std::vector<bool>(v2.lattice.size(), true), 5e-4);
  for (const auto& t : plain.tendons) EXPECT_FALSE(IsDomeSpring(t.Get("name"))) << t.Get("name");
}

/// A skin part's linear dynamics over its pins' joints (per pin: normal, shear y, shear z):
/// stiffness from the joints' springs and every tendon, each joint's damping.
struct LatticeDynamics {
  Eigen::MatrixXd K;
  Eigen::VectorXd c;
};

LatticeDynamics DynamicsOf(const SkinPart& part, int n_pins) {
  std::map<std::string, int> dof;
  for (int i = 0; i < n_pins; ++i) {
    dof[SkinNames{}.PinJoint(i)] = 3 * i;
    dof[SkinNames{}.PinShearJoint(i, 'y')] = 3 * i + 1;
    dof[SkinNames{}.PinShearJoint(i, 'z')] = 3 * i + 2;
  }
  LatticeDynamics d{Eigen::MatrixXd::Zero(3 * n_pins, 3 * n_pins), Eigen::VectorXd::Zero(3 * n_pins)};
  for (const auto& [i, body] : PinBodies(part)) {
    for (const auto& j : body->children()) {
      if (j.tag() != "joint") continue;
      const int k = dof.at(j.Get("name"));
      d.K(k, k) += std::stod(j.Get("stiffness"));
      d.c(k) = std::stod(j.Get("damping"));
    }
  }
  AddTendonStiffness(d.K, part, dof, [](const std::string&) { return true; });
  return d;
}

/// Largest growth factor per step of MuJoCo 2.2.2's Euler step on those dynamics (each pin
/// of mass m on three orthogonal slides; joint damping implicit, springs explicit):
/// (M + h C) v' = M v - h K q, q' = q + h v'.
double EulerStepGrowth(const LatticeDynamics& d, double mass, double h) {
  const int n = static_cast<int>(d.c.size());
  const Eigen::VectorXd inv = (mass + h * d.c.array()).inverse().matrix();
  const Eigen::MatrixXd B = inv.asDiagonal() * d.K;  // (M + hC)^-1 K
  Eigen::MatrixXd A(2 * n, 2 * n);
  A.topLeftCorner(n, n) = Eigen::MatrixXd::Identity(n, n) - h * h * B;
  A.topRightCorner(n, n) = (h * mass * inv).asDiagonal();
  A.bottomLeftCorner(n, n) = -h * B;
  A.bottomRightCorner(n, n) = (mass * inv).asDiagonal();
  return Eigen::EigenSolver<Eigen::MatrixXd>(A, false).eigenvalues().cwiseAbs().maxCoeff();
}

// A dome spring couples its pin's normal and shear joints: along the dome normal it is
// k_n / cos^2 (the bound takes the widest pin), its shear rows enter the shear bound, and the
// implicit dampers act on it in series, so both joints take the normal mode's floor. The
// whole lattice's Euler step (every pin collidable, so every pin carries a spring) then
// decays, even with the gel 100 times stiffer, where the physical dampers let it grow.
TEST_F(FingerprintSkinPartTest, DomeSpringsLatticeStepDecaysWithTheDampingFloors) {
  TACTIP_LONG_EXPERIMENT();
  const DomeV2 preset;
  double widest = 0.0;
  for (const auto& pin : preset.lattice.pins) widest = std::max(widest, std::acos(pin.normal[0]));
  EXPECT_NEAR(preset.mech.dome_gain, 1.0 / (std::cos(widest) * std::cos(widest)), 1e-9);
  ASSERT_GT(preset.mech.dome_gain, 2.0) << "premise: v2's outer ring lies beyond 45 degrees";
  const double m = preset.mech.pin_mass_kg;
  const int n = static_cast<int>(preset.lattice.size());
  EXPECT_LT(EulerStepGrowth(DynamicsOf(preset.part, n), m, 5e-4), 1.0);
  const DomeV2 central(2.5e-4, {{"membrane_links", "central"}});
  EXPECT_LT(EulerStepGrowth(DynamicsOf(central.part, n), m, 2.5e-4), 1.0);
  for (const auto& [gel, dt] : {std::pair{"1000", 1e-3}, std::pair{"10000", 5e-4}}) {
    SCOPED_TRACE(fmt::format("gel {} kPa at {} s", gel, dt));
    const DomeV2 stiff(dt, {{"gel_modulus_kpa", gel}});
    LatticeDynamics d = DynamicsOf(stiff.part, n);
    EXPECT_LT(EulerStepGrowth(d, m, dt), 1.0 + 1e-9);
    // The physical dampers alone would not do.
    for (int i = 0; i < n; ++i) {
      d.c(3 * i) = stiff.mech.pin_damping_Ns_m;
      d.c(3 * i + 1) = d.c(3 * i + 2) = stiff.mech.tip_damping_Ns_m;
    }
    EXPECT_GT(EulerStepGrowth(d, m, dt), 1.01);
  }
  // The shell has no per-pin shear joints to slide over the dome: the key is ignored.
  SkinConfig shell = preset.skin;
  shell.coupling = "shell";
  EXPECT_EQ(SkinMechanics::From(shell, preset.lattice).dome_gain, 1.0);
  EXPECT_EQ(SkinMechanics::From(shell, preset.lattice).dome_shear_row_N_m, 0.0);
}

TEST(FingerprintMechanicsTest, CentralLinkStiffnessIsTheLinkInSeriesWithTheRidgesRadialShare) {
  const SkinConfig v2 = PresetSkin("fingerprint-v2");
  const SkinMechanics m = SkinMechanics::From(v2, PinLattice::Build(v2));
  EXPECT_FALSE(m.central_links) << "isotropic links by default";
  EXPECT_NEAR(m.CentralLinkStiffness(1.0), m.k_couple_N_m, 1e-9 * m.k_couple_N_m);
  EXPECT_NEAR(m.CentralLinkStiffness(0.0), m.k_link_N_m, 1e-9 * m.k_link_N_m);
  EXPECT_NEAR(1.0 / m.CentralLinkStiffness(0.5), 1.0 / m.k_link_N_m + 0.5 / m.k_rock_N_m, 1e-12);
  // Without ridges (the smooth pattern in a membrane lattice) a link is the membrane spring.
  SkinConfig smooth;
  smooth.coupling = "membrane";
  smooth.membrane_links = "central";
  const SkinMechanics s = SkinMechanics::From(smooth, PinLattice::Build(smooth));
  EXPECT_TRUE(s.central_links);
  EXPECT_EQ(s.CentralLinkStiffness(1.0), s.k_link_N_m);
  // Only a membrane lattice has links.
  smooth.coupling = "shell";
  EXPECT_FALSE(SkinMechanics::From(smooth, PinLattice::Build(smooth)).central_links);
}

TEST_F(FingerprintSkinPartTest, ShellCouplingKeepsDofsOnEveryPinAndHasNoMembraneSprings) {
  SkinConfig v2 = PresetSkin("fingerprint-v2");
  v2.coupling = "shell";
  const PinLattice lat = PinLattice::Build(v2);
  std::vector<bool> coll(lat.size(), false);
  coll[0] = true;
  const SkinPart part = BuildSkin(v2, ContactConfig{}, lat, coll, 2e-3);
  for (const auto& [i, body] : PinBodies(part)) {
    int joints = 0;
    for (const auto& c : body->children()) joints += c.tag() == "joint" ? 1 : 0;
    EXPECT_EQ(joints, 1) << "pin " << i << ": only the normal DOF in shell mode";
  }
  for (const auto& t : part.tendons) EXPECT_EQ(t.Get("name").rfind("membrane_", 0), std::string::npos);
}

TEST_F(FingerprintSkinPartTest, FingerprintRailSceneCompilesWithAFullShearLatticeAndNormalDofsPerCollidablePin) {
  for (const char* name : {"fingerprint-v1", "fingerprint-v2"}) {
    SCOPED_TRACE(name);
    RailSceneSpec spec;
    spec.skin = PresetSkin(name);
    spec.rail.stimulus = "acrylic";
    spec.external_markers = true;  // the incipient rig records every outer contact point
    spec.max_depth_m = 3.1e-3;
    const BuiltScene scene = BuildRailScene(spec);
    EXPECT_EQ(scene.n_pins, std::string(name) == "fingerprint-v1" ? 91 : 127);
    ASSERT_LT(scene.n_collidable, scene.n_pins);
    EXPECT_NE(scene.xml.find("name=\"tactip/membrane_"), std::string::npos);
    const CompiledModel m = CompiledModel::FromXml(scene.xml);
    // Rig: arm x, arm z, rail slide; skin: two shear DOFs per pin, a normal DOF per collidable pin.
    EXPECT_EQ(m.nv(), 3 + 2 * scene.n_pins + scene.n_collidable);
    const PinLattice lat = PinLattice::Build(spec.skin);
    const auto coll = RailCollidablePins(spec.skin, lat, spec.rail, spec.max_depth_m);
    for (size_t i = 0; i < lat.size(); ++i) {
      const int pin = static_cast<int>(i);
      EXPECT_NO_THROW(m.SiteId(SkinNames{"tactip/"}.PinSite(pin)));
      EXPECT_NO_THROW(m.SiteId(SkinNames{"tactip/"}.PinOuterSite(pin)));
      EXPECT_NO_THROW(m.JointId(SkinNames{"tactip/"}.PinShearJoint(pin, 'z'))) << "pin " << i;
      if (coll[i]) {
        EXPECT_NO_THROW(m.JointId(SkinNames{"tactip/"}.PinJoint(pin))) << "pin " << i;
      } else {
        EXPECT_THROW(m.JointId(SkinNames{"tactip/"}.PinJoint(pin)), ModelError) << "pin " << i;
      }
    }
    // A deeper press reaches more pins and adds exactly one (normal) DOF for each.
    spec.max_depth_m = 6.5e-3;
    const BuiltScene deeper = BuildRailScene(spec);
    ASSERT_GT(deeper.n_collidable, scene.n_collidable);
    EXPECT_EQ(CompiledModel::FromXml(deeper.xml).nv(), 3 + 2 * deeper.n_pins + deeper.n_collidable);
  }
}

// ---- Validation rules ----------------------------------------------------------------

TEST(FingerprintConfigTest, PatternBeyondTheEquatorIsRejectedNamingTheKey) {
  SkinConfig s = PresetSkin("fingerprint-v2");
  s.rim = "free";              // the lattice's own rule (a clamped rim needs room beyond it: RimAnchorTest)
  s.pattern_radius_mm = 31.0;  // < pi/2 * 20 = 31.42 mm
  EXPECT_NO_THROW(ValidateConfig(s));
  s.pattern_radius_mm = 32.0;
  const std::string msg = InputErrorOf([&] { ValidateConfig(s); });
  EXPECT_NE(msg.find("skin.pattern_radius_mm = 32: lattice reaches"), std::string::npos) << msg;
  // The hexagonal ring count does not matter for a fingerprint pattern.
  s.pattern_radius_mm = 18.0;
  s.rings = 12;
  EXPECT_NO_THROW(ValidateConfig(s));
}

// Measured: v1's pivoting edge pins flicker in and out of contact while held on dome
// springs, so v1 refuses them naming the key and the safe value; v2 takes them.
TEST(FingerprintConfigTest, DomeSpringsAreRefusedOnV1NamingTheKey) {
  SkinConfig v1 = PresetSkin("fingerprint-v1");
  v1.normal_spring = "dome";
  const std::string msg = InputErrorOf([&] { ValidateConfig(v1); });
  EXPECT_EQ(msg.rfind("skin.normal_spring = 'dome': fingerprint-v1", 0), 0u) << msg;
  EXPECT_NE(msg.find("use axial"), std::string::npos) << msg;
  SkinConfig v2 = PresetSkin("fingerprint-v2");
  v2.normal_spring = "dome";
  EXPECT_NO_THROW(ValidateConfig(v2));
}

// The orthotropic membrane is the concentric ridges' corrugated sheet: a smooth membrane
// lattice (hexagonal, no ridges) refuses it naming the key.
TEST(FingerprintConfigTest, OrthotropicMembraneNeedsAFingerprintPattern) {
  SkinConfig s;
  s.coupling = "membrane";
  s.membrane_links = "orthotropic";
  const std::string msg = InputErrorOf([&] { ValidateConfig(s); });
  EXPECT_EQ(msg.rfind("skin.membrane_links = 'orthotropic': ", 0), 0u) << msg;
  EXPECT_NE(msg.find("fingerprint pattern"), std::string::npos) << msg;
  SkinConfig v1 = PresetSkin("fingerprint-v1");
  v1.membrane_links = "orthotropic";
  EXPECT_NO_THROW(ValidateConfig(v1));
}

TEST(FingerprintConfigTest, PatternNarrowerThanOneRingIsRejected) {
  SkinConfig s = PresetSkin("fingerprint-v1");
  s.pattern_radius_mm = 3.0;  // ridge spacing 4 mm
  const std::string msg = InputErrorOf([&] { ValidateConfig(s); });
  EXPECT_NE(msg.find("skin.pattern_radius_mm = 3:"), std::string::npos) << msg;
  EXPECT_NE(msg.find("ridge_spacing_mm"), std::string::npos) << msg;
}

TEST(FingerprintConfigTest, V2PinsMustNotReachBeyondTheSkinUnderTheWave) {
  SkinConfig s = PresetSkin("fingerprint-v2");  // ridge 2 mm + skin 1 mm
  s.pin_length_mm = 3.0;
  EXPECT_NO_THROW(ValidateConfig(s));
  s.pin_length_mm = 3.5;
  const std::string msg = InputErrorOf([&] { ValidateConfig(s); });
  EXPECT_NE(msg.find("skin.pin_length_mm = 3.5:"), std::string::npos) << msg;
  EXPECT_NE(msg.find("fingerprint-v2"), std::string::npos) << msg;
  // The rule is specific to v2: v1 pins reach out into their ridges.
  SkinConfig v1 = PresetSkin("fingerprint-v1");
  v1.pin_length_mm = 3.5;
  EXPECT_NO_THROW(ValidateConfig(v1));
}

}  // namespace
}  // namespace tactip
