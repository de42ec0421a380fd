// The exact quasi-static shear solver (the dome check's reference) on lattices solved by
// hand.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "scenarios/quasi_static_shear.h"
#include "sim/base/errors.h"

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

}  // namespace
}  // namespace tactip
