#include "scenarios/studies/contact_checks/quasi_static_shear.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <Eigen/Dense>

#include "sim/base/errors.h"

namespace tactip {

namespace {

using Vec2 = std::array<double, 2>;
constexpr Vec2 kPlateAxis = {1.0, 0.0};  // the plate moves along y

// The lattice's 2n x 2n stiffness (DOF 2i: pin i along y, 2i + 1: along z).
Eigen::MatrixXd StiffnessMatrix(const LatticeShearStiffness& s) {
  const int n = static_cast<int>(s.k_tip_N_m.size());
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  for (int i = 0; i < n; ++i) K(2 * i, 2 * i) = K(2 * i + 1, 2 * i + 1) = s.k_tip_N_m[i];
  for (const auto& l : s.links) {
    const double block[2][2] = {{l.k_yy, l.k_yz}, {l.k_yz, l.k_zz}};
    for (int r = 0; r < 2; ++r) {
      for (int c = 0; c < 2; ++c) {
        K(2 * l.a + r, 2 * l.a + c) += block[r][c];
        K(2 * l.b + r, 2 * l.b + c) += block[r][c];
        K(2 * l.a + r, 2 * l.b + c) -= block[r][c];
        K(2 * l.b + r, 2 * l.a + c) -= block[r][c];
      }
    }
  }
  for (const auto& mode : s.modes) {
    for (int r = 0; r < 6; ++r) {
      for (int c = 0; c < 6; ++c) {
        K(2 * mode.pins[r / 2] + r % 2, 2 * mode.pins[c / 2] + c % 2) += mode.k_N_m * mode.coef[r] * mode.coef[c];
      }
    }
  }
  return K;
}

// The pins' states between two releases; a slipped pin's friction is mu N_i along dir.
struct ShearState {
  std::vector<std::uint8_t> stuck, slipped;
  std::vector<Vec2> dir;
};

// One segment of the quasi-static solution between two releases: with the stuck set fixed,
// every force is affine in the plate displacement delta. Q = q0 + q1 delta (along y).
struct Segment {
  double delta0, q0, q1;
};

// The next release of a segment: the pin, the plate displacement and its force's direction.
struct Release {
  int pin = -1;
  double at = std::numeric_limits<double>::infinity();
  Vec2 dir = kPlateAxis;
};

// Where a stuck pin's friction force f0 + delta f1 leaves the disc |f| <= limit (the larger
// root of |f0 + delta f1|^2 = limit^2; infinity when the force does not grow).
double LeavesCone(const Vec2& f0, const Vec2& f1, double limit) {
  const double a = f1[0] * f1[0] + f1[1] * f1[1];
  if (!(a > 0.0)) return std::numeric_limits<double>::infinity();
  const double b = f0[0] * f1[0] + f0[1] * f1[1];
  const double c = f0[0] * f0[0] + f0[1] * f0[1] - limit * limit;
  const double disc = b * b - a * c;
  if (disc < 0.0) return std::numeric_limits<double>::infinity();
  const double d = (-b + std::sqrt(disc)) / a;
  // A force that changes only against the plate's pull (f1 along -y, no z share) is being
  // unloaded by the lattice: it would leave the disc only after reversing through zero, in the
  // direction opposite to the load, which the monotone ramp to gross slip does not reach.
  return f1[0] > 0.0 || std::abs(f1[1]) > 0.0 ? d : std::numeric_limits<double>::infinity();
}

// The lattice's displacements u = u0 + delta u1 with the stuck set fixed. Rigid stick
// (presliding 0): stuck pins move with the plate, the others are solved; otherwise every
// pin is solved, each stuck pin tied to the plate by its pre-sliding spring.
struct Displacements {
  Eigen::VectorXd u0, u1;
};

// The equations of the unknown DOFs U: K_UU u_U = b + delta k (b: the slipped pins'
// friction; k: the plate's pull through the stuck pins), and the stuck pins' u1.
struct UnknownSystem {
  std::vector<int> U;
  Eigen::MatrixXd Kuu;
  Eigen::VectorXd b, k, stuck_u1;
};

UnknownSystem Assemble(const Eigen::MatrixXd& K, const std::vector<double>& springs,
                       const std::vector<double>& friction_N, const ShearState& s, bool rigid) {
  const int dofs = static_cast<int>(K.rows());
  UnknownSystem sys;
  sys.stuck_u1 = Eigen::VectorXd::Zero(dofs);
  for (int d = 0; d < dofs; ++d) {
    if (rigid && s.stuck[d / 2]) {
      if (d % 2 == 0) sys.stuck_u1(d) = 1.0;
    } else {
      sys.U.push_back(d);
    }
  }
  const auto m = static_cast<Eigen::Index>(sys.U.size());
  sys.Kuu.resize(m, m);
  sys.b.resize(m);
  sys.k.resize(m);
  for (Eigen::Index a = 0; a < m; ++a) {
    const int d = sys.U[a], pin = d / 2, c = d % 2;
    sys.b(a) = s.slipped[pin] ? friction_N[pin] * s.dir[pin][c] : 0.0;
    sys.k(a) = springs[pin] * kPlateAxis[c] - K.row(d).dot(sys.stuck_u1);
    for (Eigen::Index e = 0; e < m; ++e) sys.Kuu(a, e) = K(d, sys.U[e]);
    sys.Kuu(a, a) += springs[pin];
  }
  return sys;
}

Displacements Solve(const UnknownSystem& sys) {
  Displacements out{Eigen::VectorXd::Zero(sys.stuck_u1.size()), sys.stuck_u1};
  if (sys.U.empty()) return out;
  const Eigen::LDLT<Eigen::MatrixXd> ldlt(sys.Kuu);
  const Eigen::VectorXd x0 = ldlt.solve(sys.b), x1 = ldlt.solve(sys.k);
  for (size_t a = 0; a < sys.U.size(); ++a) out.u0(sys.U[a]) = x0(a), out.u1(sys.U[a]) = x1(a);
  return out;
}

// The slipped pins' turn rates d(theta_i)/d(delta), s_i = (cos theta_i, sin theta_i): each
// pin's friction turns so that it keeps sliding along it — its slip rate (1, 0) - du_i/ddelta
// parallel to s_i, i.e. p_i . du_i/ddelta = p_i . (1, 0) with p_i = (-sin, cos) — while the
// lattice stays in equilibrium: K_UU du_U/ddelta = k + sum_i mu N_i p_i dtheta_i/ddelta.
std::vector<double> TurnRates(const UnknownSystem& sys, const std::vector<double>& friction_N, const ShearState& s) {
  std::vector<int> slipped, row_of(s.slipped.size() * 2, -1);
  for (size_t a = 0; a < sys.U.size(); ++a) row_of[sys.U[a]] = static_cast<int>(a);
  for (size_t i = 0; i < s.slipped.size(); ++i) {
    if (s.slipped[i]) slipped.push_back(static_cast<int>(i));
  }
  const auto m = static_cast<Eigen::Index>(sys.U.size()), p = static_cast<Eigen::Index>(slipped.size());
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(m + p, m + p);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(m + p);
  M.topLeftCorner(m, m) = sys.Kuu;
  rhs.head(m) = sys.k;
  for (Eigen::Index q = 0; q < p; ++q) {
    const int pin = slipped[q];
    const Vec2 perp = {-s.dir[pin][1], s.dir[pin][0]};
    for (int c = 0; c < 2; ++c) {
      const int row = row_of[2 * pin + c];
      M(row, m + q) = -friction_N[pin] * perp[c];
      M(m + q, row) = perp[c];
    }
    rhs(m + q) = perp[0];
  }
  const Eigen::VectorXd x = M.partialPivLu().solve(rhs);
  std::vector<double> rates(s.slipped.size(), 0.0);
  for (Eigen::Index q = 0; q < p; ++q) rates[slipped[q]] = x(m + q);
  return rates;
}

// Turns each slipped pin's friction by its turn rate over a step of plate travel.
void Turn(const std::vector<double>& rates, double step, ShearState& s) {
  for (size_t i = 0; i < rates.size(); ++i) {
    if (!s.slipped[i]) continue;
    const double theta = std::atan2(s.dir[i][1], s.dir[i][0]) + rates[i] * step;
    s.dir[i] = {std::cos(theta), std::sin(theta)};
  }
}

Segment SolveSegment(const Eigen::MatrixXd& K, const std::vector<double>& friction_N, double presliding_m,
                     const ShearState& s, double delta, Release* next, UnknownSystem* system) {
  const int n = static_cast<int>(friction_N.size());
  const bool rigid = !(presliding_m > 0.0);
  std::vector<double> springs(n, 0.0);
  for (int i = 0; i < n; ++i) springs[i] = s.stuck[i] && !rigid ? friction_N[i] / presliding_m : 0.0;
  *system = Assemble(K, springs, friction_N, s, rigid);
  const Displacements u = Solve(*system);
  // Each stuck pin's friction f = f0 + delta f1: its spring, or (rigid) the lattice's pull.
  Segment seg{delta, 0.0, 0.0};
  *next = Release{};
  for (int i = 0; i < n; ++i) {
    if (s.slipped[i]) seg.q0 += friction_N[i] * s.dir[i][0];
    if (!s.stuck[i]) continue;
    Vec2 f0{}, f1{};
    for (int c = 0; c < 2; ++c) {
      const int d = 2 * i + c;
      f0[c] = rigid ? K.row(d).dot(u.u0) : -springs[i] * u.u0(d);
      f1[c] = rigid ? K.row(d).dot(u.u1) : springs[i] * (kPlateAxis[c] - u.u1(d));
    }
    seg.q0 += f0[0];
    seg.q1 += f1[0];
    const double at = LeavesCone(f0, f1, friction_N[i]);
    if (at < next->at) {
      const Vec2 f = {f0[0] + at * f1[0], f0[1] + at * f1[1]};
      const double norm = std::hypot(f[0], f[1]);
      *next = Release{i, at, norm > 0.0 ? Vec2{f[0] / norm, f[1] / norm} : kPlateAxis};
    }
  }
  return seg;
}

// Q / (mu P) on a uniform grid of plate displacement up to gross slip. Q is continuous at a
// release, so either segment gives it there.
void FillGrid(const std::vector<Segment>& segments, double gross_delta, double mu_P, int grid_points,
              QuasiStaticShear& out) {
  if (grid_points <= 1) return;
  size_t k = 0;
  for (int g = 0; g < grid_points; ++g) {
    const double d = gross_delta * g / (grid_points - 1);
    while (k + 1 < segments.size() && d >= segments[k + 1].delta0) ++k;
    out.grid_delta_m.push_back(d);
    out.grid_q.push_back((segments[k].q0 + segments[k].q1 * d) / mu_P);
  }
}

// How many times, over the travel to gross slip, the slipped pins' friction directions are
// turned (central links). On the v2 lattice the releases differ from those at 4000 steps by at
// most 2.5e-4 Q/muP at 500 steps, 8e-5 at 1000 and 2e-5 at 2000 (first order in the step).
constexpr int kTurnSteps = 1000;

// Whether the stiffness couples any pin's y to any pin's z (a central link neither along nor
// across y; the orthotropic membrane's triangles).
bool CouplesComponents(const Eigen::MatrixXd& K) {
  for (Eigen::Index r = 0; r < K.rows(); r += 2) {
    for (Eigen::Index c = 1; c < K.cols(); c += 2) {
      if (K(r, c) != 0.0) return true;
    }
  }
  return false;
}

// Shears the lattice from delta = 0 until every contacting pin slips, one segment per release
// (and, if turn_step > 0, per turn of the slipped pins' friction every turn_step of travel,
// each from its direction at release to the one it slides along); fills
// out's releases and gross slip and returns the segments.
std::vector<Segment> ShearToGrossSlip(const Eigen::MatrixXd& K, const std::vector<double>& friction_N, double mu_P,
                                      double presliding_m, double turn_step, ShearState& state, QuasiStaticShear& out) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  std::vector<Segment> segments;
  double delta = 0.0, turn_at = turn_step > 0.0 ? turn_step : kInf;
  while (std::count(state.stuck.begin(), state.stuck.end(), 1) > 0) {
    Release next;
    UnknownSystem system;
    segments.push_back(SolveSegment(K, friction_N, presliding_m, state, delta, &next, &system));
    if (next.pin < 0 && (turn_at == kInf || segments.size() > 100u * kTurnSteps)) {
      throw SimulationError("quasi-static shear: the stuck pins carry no load as the plate moves");
    }
    if (next.pin >= 0 && next.at <= turn_at) {
      delta = std::max(delta, next.at);
      const Segment& last = segments.back();
      out.release_delta_m[next.pin] = delta;
      out.release_q[next.pin] = (last.q0 + last.q1 * delta) / mu_P;
      state.stuck[next.pin] = 0;
      state.slipped[next.pin] = 1;
      state.dir[next.pin] = next.dir;
      continue;
    }
    // Explicit in the angle: a step turns a slipped pin by (its turn rate) x (step), a small
    // fraction of a radian where the lattice is soft against the pins' friction.
    Turn(TurnRates(system, friction_N, state), turn_at - delta, state);
    delta = turn_at;
    turn_at = delta + turn_step;
  }
  out.gross_delta_m = delta;
  return segments;
}

}  // namespace

LatticeShearStiffness LatticeShearStiffness::Isotropic(const PinLattice& lattice, const std::vector<double>& k_tip_N_m,
                                                       double k_couple_N_m) {
  LatticeShearStiffness s;
  s.k_tip_N_m = k_tip_N_m;
  for (const auto& e : lattice.neighbours) s.links.push_back({e[0], e[1], k_couple_N_m, 0.0, k_couple_N_m});
  return s;
}

LatticeShearStiffness LatticeShearStiffness::Of(const PinLattice& lattice, const SkinMechanics& mech) {
  std::vector<double> k_tip;
  k_tip.reserve(lattice.pins.size());
  for (const auto& pin : lattice.pins) k_tip.push_back(mech.TipStiffness(pin.ring));
  if (mech.orthotropic_links) {
    LatticeShearStiffness s;
    s.k_tip_N_m = std::move(k_tip);
    s.modes = OrthotropicMembraneModes(mech, lattice);
    return s;
  }
  if (!mech.central_links) return Isotropic(lattice, k_tip, mech.k_couple_N_m);
  LatticeShearStiffness s;
  s.k_tip_N_m = std::move(k_tip);
  for (const auto& e : lattice.neighbours) {
    const SkinMechanics::CentralLink l = mech.CentralLinkBetween(lattice.pins[e[0]], lattice.pins[e[1]]);
    s.links.push_back({e[0], e[1], l.k_N_m * l.ey * l.ey, l.k_N_m * l.ey * l.ez, l.k_N_m * l.ez * l.ez});
  }
  return s;
}

QuasiStaticShear SolveQuasiStaticShear(const LatticeShearStiffness& stiffness, const std::vector<double>& normal_N,
                                       const std::vector<std::uint8_t>& in_contact, double mu, int grid_points,
                                       double presliding_m) {
  const size_t n = stiffness.k_tip_N_m.size();
  if (normal_N.size() != n || in_contact.size() != n) {
    throw std::invalid_argument("SolveQuasiStaticShear: one shear stiffness, normal load and contact flag per pin");
  }
  const Eigen::MatrixXd K = StiffnessMatrix(stiffness);
  QuasiStaticShear out;
  out.release_q.assign(n, std::nan(""));
  out.release_delta_m.assign(n, std::nan(""));
  ShearState state{std::vector<std::uint8_t>(n, 0), std::vector<std::uint8_t>(n, 0), std::vector<Vec2>(n, kPlateAxis)};
  std::vector<double> friction_N(n, 0.0);
  double mu_P = 0.0;
  for (size_t i = 0; i < n; ++i) {
    if (!in_contact[i]) continue;
    state.stuck[i] = 1;
    friction_N[i] = mu * normal_N[i];
    mu_P += friction_N[i];
  }
  if (!(mu_P > 0.0)) throw SimulationError("quasi-static shear: no pin in contact");
  // A first pass with each slipped pin's friction held at its release direction (exact where
  // the links leave the components uncoupled); where they couple them, a second pass turns it
  // with the slip every 1/kTurnSteps of the first pass's travel to gross slip.
  ShearState held = state;
  QuasiStaticShear first = out;
  std::vector<Segment> segments = ShearToGrossSlip(K, friction_N, mu_P, presliding_m, 0.0, held, first);
  if (!CouplesComponents(K)) {
    FillGrid(segments, first.gross_delta_m, mu_P, grid_points, first);
    return first;
  }
  segments = ShearToGrossSlip(K, friction_N, mu_P, presliding_m, first.gross_delta_m / kTurnSteps, state, out);
  FillGrid(segments, out.gross_delta_m, mu_P, grid_points, out);
  return out;
}

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
  if (k_tip_N_m.size() != lattice.pins.size()) {
    throw std::invalid_argument("SolveQuasiStaticShear: one shear stiffness, normal load and contact flag per pin");
  }
  return SolveQuasiStaticShear(LatticeShearStiffness::Isotropic(lattice, k_tip_N_m, k_couple_N_m), normal_N,
                               in_contact, mu, grid_points, presliding_m);
}

}  // namespace tactip
