#include "scenarios/quasi_static_shear.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <Eigen/Dense>

#include "sim/base/errors.h"

namespace tactip {

namespace {

// One segment of the quasi-static solution between two releases: with the stuck set S
// fixed, every force is affine in the plate displacement delta. Returns the segment
// (Q = q0 + q1 delta) and the next pin to release (or -1) at displacement `*release_at`.
// Rigid stick (presliding 0): stuck pins move with the plate. Otherwise each stuck pin is
// tied to the plate by its pre-sliding spring mu N_i / presliding, as in the friction pass.
struct Segment {
  double delta0, q0, q1;
};

Segment SolveSegment(const Eigen::MatrixXd& K, const std::vector<double>& normal_N, double mu, double presliding_m,
                     const std::vector<std::uint8_t>& stuck, const std::vector<std::uint8_t>& slipped, double delta,
                     int* release, double* release_at) {
  const int n = static_cast<int>(K.rows());
  // Unknown pins U (all pins, or the unstuck ones under rigid stick): K_UU u = b + delta k.
  std::vector<int> U;
  for (int i = 0; i < n; ++i) {
    if (presliding_m > 0.0 || !stuck[i]) U.push_back(i);
  }
  const auto spring = [&](int i) { return stuck[i] && presliding_m > 0.0 ? mu * normal_N[i] / presliding_m : 0.0; };
  Eigen::VectorXd x0 = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(U.size())), x1 = x0;
  if (!U.empty()) {
    Eigen::MatrixXd Kuu(U.size(), U.size());
    Eigen::VectorXd b(U.size()), k(U.size());
    for (size_t a = 0; a < U.size(); ++a) {
      b(a) = slipped[U[a]] ? mu * normal_N[U[a]] : 0.0;
      k(a) = spring(U[a]);
      for (int j = 0; j < n; ++j) {
        if (presliding_m <= 0.0 && stuck[j]) k(a) -= K(U[a], j);
      }
      for (size_t c = 0; c < U.size(); ++c) Kuu(a, c) = K(U[a], U[c]);
      Kuu(a, a) += spring(U[a]);
    }
    const Eigen::LDLT<Eigen::MatrixXd> ldlt(Kuu);
    x0 = ldlt.solve(b);
    x1 = ldlt.solve(k);
  }
  std::vector<double> u0(n, 0.0), u1(n, 0.0);  // u_i = u0 + delta u1
  for (size_t a = 0; a < U.size(); ++a) u0[U[a]] = x0(a), u1[U[a]] = x1(a);
  for (int i = 0; i < n; ++i) {
    if (presliding_m <= 0.0 && stuck[i]) u1[i] = 1.0;
  }
  // Each stuck pin's friction f = f0 + delta f1: its spring, or (rigid) the lattice's pull.
  Segment seg{delta, 0.0, 0.0};
  *release = -1;
  *release_at = std::numeric_limits<double>::infinity();
  for (int i = 0; i < n; ++i) {
    if (slipped[i]) seg.q0 += mu * normal_N[i];
    if (!stuck[i]) continue;
    double f0 = 0.0, f1 = 0.0;
    if (presliding_m > 0.0) {
      f0 = -spring(i) * u0[i];
      f1 = spring(i) * (1.0 - u1[i]);
    } else {
      for (int j = 0; j < n; ++j) f0 += K(i, j) * u0[j], f1 += K(i, j) * u1[j];
    }
    seg.q0 += f0;
    seg.q1 += f1;
    if (f1 <= 0.0) continue;
    const double d = (mu * normal_N[i] - f0) / f1;
    if (d < *release_at) *release_at = d, *release = i;
  }
  return seg;
}

}  // namespace

QuasiStaticShear SolveQuasiStaticShear(const PinLattice& lattice, double k_tip_N_m, double k_couple_N_m,
                                       const std::vector<double>& normal_N, const std::vector<std::uint8_t>& in_contact,
                                       double mu, int grid_points, double presliding_m) {
  return SolveQuasiStaticShear(lattice, std::vector<double>(lattice.pins.size(), k_tip_N_m), k_couple_N_m, normal_N,
                               in_contact, mu, grid_points, presliding_m);
}

QuasiStaticShear SolveQuasiStaticShear(const PinLattice& lattice, const std::vector<double>& k_tip_N_m,
                                       double k_couple_N_m, const std::vector<double>& normal_N,
                                       const std::vector<std::uint8_t>& in_contact, double mu, int grid_points,
                                       double presliding_m) {
  const int n = static_cast<int>(lattice.pins.size());
  if (static_cast<int>(normal_N.size()) != n || static_cast<int>(in_contact.size()) != n ||
      static_cast<int>(k_tip_N_m.size()) != n) {
    throw std::invalid_argument("SolveQuasiStaticShear: one shear stiffness, normal load and contact flag per pin");
  }
  Eigen::MatrixXd K = Eigen::VectorXd::Map(k_tip_N_m.data(), n).asDiagonal();
  for (const auto& e : lattice.neighbours) {
    K(e[0], e[0]) += k_couple_N_m;
    K(e[1], e[1]) += k_couple_N_m;
    K(e[0], e[1]) -= k_couple_N_m;
    K(e[1], e[0]) -= k_couple_N_m;
  }
  QuasiStaticShear out;
  out.release_q.assign(n, std::nan(""));
  out.release_delta_m.assign(n, std::nan(""));
  double mu_P = 0.0;
  std::vector<std::uint8_t> stuck(n, 0), slipped(n, 0);
  for (int i = 0; i < n; ++i) {
    if (!in_contact[i]) continue;
    stuck[i] = 1;
    mu_P += mu * normal_N[i];
  }
  if (!(mu_P > 0.0)) throw SimulationError("quasi-static shear: no pin in contact");
  // Release the pins one by one; every force is affine in delta between two releases.
  std::vector<Segment> segments;
  double delta = 0.0;
  while (std::count(stuck.begin(), stuck.end(), 1) > 0) {
    int release = -1;
    double at = 0.0;
    segments.push_back(SolveSegment(K, normal_N, mu, presliding_m, stuck, slipped, delta, &release, &at));
    if (release < 0) throw SimulationError("quasi-static shear: the stuck pins carry no load as the plate moves");
    delta = std::max(delta, at);
    const Segment& last = segments.back();
    out.release_delta_m[release] = delta;
    out.release_q[release] = (last.q0 + last.q1 * delta) / mu_P;
    stuck[release] = 0;
    slipped[release] = 1;
  }
  out.gross_delta_m = delta;
  if (grid_points > 1) {
    size_t k = 0;
    for (int g = 0; g < grid_points; ++g) {
      const double d = delta * g / (grid_points - 1);
      // Q is continuous at a release, so either segment gives it there.
      while (k + 1 < segments.size() && d >= segments[k + 1].delta0) ++k;
      out.grid_delta_m.push_back(d);
      out.grid_q.push_back((segments[k].q0 + segments[k].q1 * d) / mu_P);
    }
  }
  return out;
}

}  // namespace tactip
