// The exact quasi-static shear solver (the dome check's reference) on lattices solved by
// hand.

#include <gtest/gtest.h>

#include <array>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "models/skin.h"
#include "scenarios/studies/contact_checks/quasi_static_shear.h"
#include "scenarios/rail/rail.h"
#include "sim/base/errors.h"
#include "tests/long_experiment.h"

namespace tactip {
namespace {

PinLattice Chain(int n) {
  PinLattice lat;
  lat.pins.resize(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) lat.pins[static_cast<size_t>(i)].index = i;
  for (int i = 0; i + 1 < n; ++i) lat.neighbours.push_back({i, i + 1});
  return lat;
}

TEST(QuasiStaticShearTest, UncoupledPinsReleaseAsTheBrushModelSays) {
  // No membrane: pin i slips at k delta = mu N_i, when Q = sum_j min(k delta, mu N_j).
  const double k = 20.0, mu = 0.8;
  const std::vector<double> N = {0.5, 0.2, 0.9, 0.0, 0.35};
  const std::vector<std::uint8_t> in = {1, 1, 1, 0, 1};
  const QuasiStaticShear qs = SolveQuasiStaticShear(Chain(5), k, 0.0, N, in, mu, 101);
  double mu_P = 0.0;
  for (size_t i = 0; i < N.size(); ++i) mu_P += in[i] ? mu * N[i] : 0.0;
  for (size_t i = 0; i < N.size(); ++i) {
    if (!in[i]) {
      EXPECT_TRUE(std::isnan(qs.release_q[i]));
      continue;
    }
    const double d = mu * N[i] / k;
    EXPECT_NEAR(qs.release_delta_m[i], d, 1e-12);
    double q = 0.0;
    for (size_t j = 0; j < N.size(); ++j) q += in[j] ? std::min(k * d, mu * N[j]) : 0.0;
    EXPECT_NEAR(qs.release_q[i], q / mu_P, 1e-12);
  }
  EXPECT_NEAR(qs.gross_delta_m, mu * 0.9 / k, 1e-12);
  ASSERT_EQ(qs.grid_q.size(), 101u);
  EXPECT_NEAR(qs.grid_q.front(), 0.0, 1e-12);
  EXPECT_NEAR(qs.grid_q.back(), 1.0, 1e-12);
  for (size_t g = 0; g < qs.grid_q.size(); ++g) {
    const double d = qs.gross_delta_m * static_cast<double>(g) / 100.0;
    double q = 0.0;
    for (size_t j = 0; j < N.size(); ++j) q += in[j] ? std::min(k * d, mu * N[j]) : 0.0;
    EXPECT_NEAR(qs.grid_q[g], q / mu_P, 1e-9) << "grid point " << g;
    EXPECT_NEAR(qs.grid_delta_m[g], d, 1e-15);
    for (size_t j = 0; j < N.size(); ++j) {
      EXPECT_EQ(qs.StuckAt(j, d), in[j] && k * d < mu * N[j]) << "pin " << j << ", grid point " << g;
    }
  }
}

TEST(QuasiStaticShearTest, PinOutOfContactPassesLoadThroughTheMembrane) {
  // Chain 0 - 1 - 2 with pin 1 out of contact: while 0 and 2 stick, pin 1 sits at
  // u1 = 2 kc d / (k + 2 kc), so pin 0 carries k d + kc (d - u1) and slips (N0 < N2) when
  // that reaches mu N0.
  const double k = 10.0, kc = 25.0, mu = 1.0, N0 = 0.2, N2 = 0.5;
  const QuasiStaticShear qs = SolveQuasiStaticShear(Chain(3), k, kc, {N0, 0.0, N2}, {1, 0, 1}, mu, 0);
  const double d0 = mu * N0 / (k + kc - 2.0 * kc * kc / (k + 2.0 * kc));
  EXPECT_NEAR(qs.release_delta_m[0], d0, 1e-12);
  EXPECT_TRUE(std::isnan(qs.release_q[1]));
  EXPECT_LT(qs.release_delta_m[0], qs.release_delta_m[2]);
  EXPECT_NEAR(qs.release_q[2], 1.0, 1e-12);
  // At pin 0's release both contact pins carry the same load by symmetry.
  EXPECT_NEAR(qs.release_q[0], 2.0 * mu * N0 / (mu * (N0 + N2)), 1e-12);
}

TEST(QuasiStaticShearTest, EachPinSlipsOnItsOwnShearStiffness) {
  // Uncoupled pins with their own springs (a clamped rim's outer ring is stiffer): pin i slips
  // at d_i = mu N_i / k_i. Pin 1, anchored four times stiffer, slips first despite its load.
  const double k0 = 10.0, k1 = 40.0, mu = 1.0, N0 = 0.3, N1 = 0.6;
  const QuasiStaticShear qs = SolveQuasiStaticShear(Chain(2), std::vector<double>{k0, k1}, 0.0, {N0, N1}, {1, 1}, mu, 0);
  EXPECT_NEAR(qs.release_delta_m[0], mu * N0 / k0, 1e-12);
  EXPECT_NEAR(qs.release_delta_m[1], mu * N1 / k1, 1e-12);
  EXPECT_NEAR(qs.release_q[1], (k0 + k1) * (mu * N1 / k1) / (mu * (N0 + N1)), 1e-12);
  EXPECT_THROW(SolveQuasiStaticShear(Chain(2), std::vector<double>{k0}, 0.0, {N0, N1}, {1, 1}, mu, 0),
               std::invalid_argument);
}

TEST(QuasiStaticShearTest, CoupledPairHandsTheSlippingPinsLagToItsNeighbour) {
  // Two pins joined by a membrane spring kc, both stuck: no stretch, so pin 0 (N0 < N1)
  // slips at d0 = mu N0 / k. Then pin 0 carries mu N0 at u0 = (mu N0 + kc d) / (k + kc),
  // and pin 1 carries k d + kc (d - u0) until that reaches mu N1.
  const double k = 10.0, kc = 40.0, mu = 1.0, N0 = 0.3, N1 = 0.6;
  const QuasiStaticShear qs = SolveQuasiStaticShear(Chain(2), k, kc, {N0, N1}, {1, 1}, mu, 0);
  const double d0 = mu * N0 / k;
  EXPECT_NEAR(qs.release_delta_m[0], d0, 1e-12);
  EXPECT_NEAR(qs.release_q[0], 2.0 * k * d0 / (mu * (N0 + N1)), 1e-12);
  // mu N1 = k d + kc d - kc (mu N0 + kc d) / (k + kc)  =>  solve for d.
  const double d1 = (mu * N1 + kc * mu * N0 / (k + kc)) / (k + kc - kc * kc / (k + kc));
  EXPECT_NEAR(qs.release_delta_m[1], d1, 1e-12);
  EXPECT_NEAR(qs.release_q[1], 1.0, 1e-12);
  EXPECT_LT(d1, mu * N1 / k) << "the membrane loads pin 1 early";
  EXPECT_TRUE(qs.grid_q.empty());
  EXPECT_THROW(SolveQuasiStaticShear(Chain(2), k, kc, {N0}, {1, 1}, mu, 0), std::invalid_argument);
  EXPECT_THROW(SolveQuasiStaticShear(Chain(2), k, kc, {N0, N1}, {0, 0}, mu, 0), SimulationError);
}


// Two pins joined by one link, as a LatticeShearStiffness with the link's 2x2 block.
LatticeShearStiffness Pair(double k_tip, double k_link, double ey, double ez) {
  LatticeShearStiffness s;
  s.k_tip_N_m = {k_tip, k_tip};
  s.links.push_back({0, 1, k_link * ey * ey, k_link * ey * ez, k_link * ez * ez});
  return s;
}

TEST(QuasiStaticShearTest, ACentralLinkAcrossTheShearCarriesNothing) {
  // A central link along z does not resist a rigid shear along y: the pins slip on their own
  // springs, at d_i = mu N_i / k, as if uncoupled.
  const double k = 10.0, kl = 40.0, mu = 1.0, N0 = 0.3, N1 = 0.6;
  const QuasiStaticShear qs = SolveQuasiStaticShear(Pair(k, kl, 0.0, 1.0), {N0, N1}, {1, 1}, mu, 0);
  EXPECT_NEAR(qs.release_delta_m[0], mu * N0 / k, 1e-12);
  EXPECT_NEAR(qs.release_delta_m[1], mu * N1 / k, 1e-12);
  // Along y the same link is the isotropic pair's coupling.
  const QuasiStaticShear along = SolveQuasiStaticShear(Pair(k, kl, 1.0, 0.0), {N0, N1}, {1, 1}, mu, 0);
  const QuasiStaticShear iso = SolveQuasiStaticShear(Chain(2), k, kl, {N0, N1}, {1, 1}, mu, 0);
  for (int i = 0; i < 2; ++i) EXPECT_NEAR(along.release_delta_m[i], iso.release_delta_m[i], 1e-12) << "pin " << i;
}

TEST(QuasiStaticShearTest, AnObliqueCentralLinkTurnsTheSlippingPinsFrictionAndPullsTheStuckPinSideways) {
  // Link at 45 degrees, block B = h [[1, 1], [1, 1]], h = kl / 2. Both stuck: no stretch, so
  // pin 0 (N0 < N1) slips at d0 = mu N0 / k along +y. Then (k I + B) u0 = B (d, 0) + mu N0 s:
  // as the plate moves on, u0 grows by (k I + B)^-1 B (1, 0) = h / (k + 2h) (1, 1) per unit d,
  // so pin 0 slips along (1, 0) less that, (k + h, -h) / (k + 2h), and its friction s turns
  // there. Pin 1 (held at (d, 0)) carries f1 = k (d, 0) + B ((d, 0) - u0), whose z share is the
  // link's sideways pull, and slips when |f1| = mu N1, before its y share alone reaches mu N1.
  const double k = 10.0, kl = 40.0, mu = 1.0, N0 = 0.1, N1 = 1.0, h = kl / 2.0;
  const QuasiStaticShear qs = SolveQuasiStaticShear(Pair(k, kl, std::sqrt(0.5), std::sqrt(0.5)), {N0, N1}, {1, 1}, mu, 0);
  EXPECT_NEAR(qs.release_delta_m[0], mu * N0 / k, 1e-12);
  // Pin 1's force with pin 0's friction along direction (sy, sz) ((k I + B)^-1 by hand).
  const auto f1 = [&](double d, double sy, double sz) {
    const double norm = std::hypot(sy, sz), det = k * (k + 2.0 * h);
    const double by = h * d + mu * N0 * sy / norm, bz = h * d + mu * N0 * sz / norm;
    const double u0y = ((k + h) * by - h * bz) / det, u0z = (-h * by + (k + h) * bz) / det;
    const double stretch = (d - u0y) - u0z;
    return std::array<double, 2>{k * d + h * stretch, h * stretch};
  };
  // Where |f1| reaches mu N1 (bisection; |f1| grows with d).
  const auto release = [&](double sy, double sz) {
    double lo = mu * N0 / k, hi = 1.0;
    for (int it = 0; it < 200; ++it) {
      const double mid = 0.5 * (lo + hi);
      const auto f = f1(mid, sy, sz);
      (std::hypot(f[0], f[1]) < mu * N1 ? lo : hi) = mid;
    }
    return lo;
  };
  const double turned = release(k + h, -h), held = release(1.0, 0.0);
  EXPECT_GT(std::abs(held - turned), 0.02 * turned) << "the turn matters (held " << held << ", turned " << turned << ")";
  EXPECT_NEAR(qs.release_delta_m[1], turned, 2e-3 * turned);
  const auto f = f1(turned, k + h, -h);
  EXPECT_GT(std::abs(f[1]), 0.1 * mu * N1) << "the link pulls pin 1 sideways";
  EXPECT_LT(f[0], mu * N1 - 1e-3) << "its y share alone would not release it yet";
  EXPECT_NEAR(qs.release_q[1], (mu * N0 * (k + h) / std::hypot(k + h, h) + f[0]) / (mu * (N0 + N1)), 2e-3);
  EXPECT_LT(qs.release_q[1], 1.0) << "gross slip below mu P: both pins' friction has turned sideways";
}

// The v2 lattice pressed by a flat plate: a Winkler (parabolic) pressure N_i = N0 (1 - r_i^2 / a^2).
struct PressedLattice {
  PinLattice lattice;
  SkinMechanics mech;
  std::vector<double> normal_N;
  std::vector<std::uint8_t> in_contact;
};

PressedLattice PressedV2(const std::string& links) {
  SkinConfig skin = LoadConfig<RailScenarioConfig>("", SkinPresetOverrides("fingerprint-v2")).skin;
  skin.membrane_links = links;
  PressedLattice p{PinLattice::Build(skin), {}, {}, {}};
  p.mech = SkinMechanics::From(skin, p.lattice);
  const double a = 0.55;  // contact radius over the dome's, about v2's pressed 10 mm
  for (const auto& pin : p.lattice.pins) {
    const double r = std::sin(pin.polar_rad);
    p.normal_N.push_back(r < a ? 0.05 * (1.0 - r * r / (a * a)) : 0.0);
    p.in_contact.push_back(r < a ? 1 : 0);
  }
  return p;
}

// The pin at the mirror image of `pin` (sign flipped on the sensor's y or z axis), or -1.
int Mirror(const PinLattice& lattice, int pin, int axis) {
  auto n = lattice.pins[static_cast<size_t>(pin)].normal;
  n[static_cast<size_t>(axis)] = -n[static_cast<size_t>(axis)];
  for (const auto& q : lattice.pins) {
    if (std::hypot(q.normal[0] - n[0], q.normal[1] - n[1], q.normal[2] - n[2]) < 1e-9) return q.index;
  }
  return -1;
}

// The pin that releases last (at gross slip).
int Last(const QuasiStaticShear& qs) {
  int last = -1;
  for (size_t i = 0; i < qs.release_delta_m.size(); ++i) {
    if (!std::isnan(qs.release_delta_m[i]) && (last < 0 || qs.release_delta_m[i] > qs.release_delta_m[static_cast<size_t>(last)])) {
      last = static_cast<int>(i);
    }
  }
  return last;
}

// Both mirrors of the sheared lattice (z -> -z, y -> -y) map the problem onto itself, so each
// contacting pin and its mirror images release together.
void ExpectMirrorPinsReleaseTogether(const PressedLattice& p, const QuasiStaticShear& qs) {
  int mirrored = 0;
  for (const auto& pin : p.lattice.pins) {
    if (!p.in_contact[static_cast<size_t>(pin.index)]) continue;
    for (int axis : {1, 2}) {
      const int m = Mirror(p.lattice, pin.index, axis);
      if (m < 0) continue;
      ++mirrored;
      EXPECT_NEAR(qs.release_delta_m[static_cast<size_t>(m)], qs.release_delta_m[static_cast<size_t>(pin.index)],
                  1e-9 * qs.gross_delta_m)
          << "pins " << pin.index << " and " << m;
    }
  }
  EXPECT_GT(mirrored, 40);
}

TEST(QuasiStaticShearTest, CentralLinksOnV2ReleaseMirrorPinsTogether) {
  TACTIP_LONG_EXPERIMENT();
  const PressedLattice p = PressedV2("central");
  ASSERT_TRUE(p.mech.central_links);
  const QuasiStaticShear qs = SolveQuasiStaticShear(LatticeShearStiffness::Of(p.lattice, p.mech), p.normal_N,
                                                    p.in_contact, 1.0, 0);
  // The plate moves along y.
  ExpectMirrorPinsReleaseTogether(p, qs);
  // A pin lets go with a sideways share in its friction, which then turns towards the plate's
  // direction as the plate drags it, so the load at gross slip comes back to mu P.
  EXPECT_NEAR(qs.release_q[static_cast<size_t>(Last(qs))], 1.0, 1e-3);
}


// The corrugated sheet is soft radially and stiff in shear, so the contact's edge is held
// hardest where the plate drags it along the ridges: the first pins to let go lie on the sides
// (more than 45 degrees from the plate's axis, the hardware's east/west), the first within 45
// degrees of the axis (south/north) only at a 15 % higher load. Central links order them the
// other way; on isotropic links the two tie (docs/fingerprint-skins.md, 'Orthotropic membrane').
double AngleFromPlateAxisDeg(const PinGeometry& pin) {
  return std::atan2(std::abs(pin.normal[2]), std::abs(pin.normal[1])) * 180.0 / std::numbers::pi;
}

// The lowest release load Q / (mu P) on the sides (> 45 degrees from the plate's axis) and
// within 45 degrees of the axis.
std::array<double, 2> FirstReleaseSidesAndAxis(const std::string& links) {
  const PressedLattice p = PressedV2(links);
  const QuasiStaticShear qs =
      SolveQuasiStaticShear(LatticeShearStiffness::Of(p.lattice, p.mech), p.normal_N, p.in_contact, 1.0, 0);
  std::array<double, 2> first = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  for (const auto& pin : p.lattice.pins) {
    const double q = qs.release_q[static_cast<size_t>(pin.index)];
    if (std::isnan(q)) continue;
    double& side = first[AngleFromPlateAxisDeg(pin) > 45.0 ? 0 : 1];
    side = std::min(side, q);
  }
  return first;
}

TEST(QuasiStaticShearTest, OrthotropicMembraneOnV2LetsTheSidesGoFirst) {
  TACTIP_LONG_EXPERIMENT();
  ASSERT_TRUE(PressedV2("orthotropic").mech.orthotropic_links);
  const auto orthotropic = FirstReleaseSidesAndAxis("orthotropic");
  EXPECT_GT(orthotropic[1], 1.1 * orthotropic[0]) << "sides " << orthotropic[0] << ", axis " << orthotropic[1];
  const auto central = FirstReleaseSidesAndAxis("central");
  EXPECT_GT(central[0], 1.5 * central[1]) << "central links: sides " << central[0] << ", axis " << central[1];
  const auto isotropic = FirstReleaseSidesAndAxis("isotropic");
  EXPECT_NEAR(isotropic[0], isotropic[1], 1e-6) << "isotropic links: the y problem has the ring's symmetry";
}

TEST(QuasiStaticShearTest, OrthotropicMembraneOnV2ReleasesMirrorPinsTogether) {
  const PressedLattice p = PressedV2("orthotropic");
  const QuasiStaticShear qs = SolveQuasiStaticShear(LatticeShearStiffness::Of(p.lattice, p.mech), p.normal_N,
                                                    p.in_contact, 1.0, 0);
  ExpectMirrorPinsReleaseTogether(p, qs);
  // The sheet couples y and z, so a slipped pin's friction turns with its slip and the load at
  // gross slip comes back to mu P (held at the direction of release it stopped at 0.964).
  EXPECT_NEAR(qs.release_q[static_cast<size_t>(Last(qs))], 1.0, 1e-3);
}

}  // namespace
}  // namespace tactip
