#include "sim/delassus.h"

#include <mujoco/mujoco.h>

#include <algorithm>

namespace tactip {

namespace {
constexpr double kRigidRowRegularization = 1e-9;  // rigid rows: relative to A's largest diagonal
constexpr double kMinCapacity = 1e-9;     // N: capacity floor in those weights
}  // namespace

Delassus::Delassus(const mjModel* m, int max_rows) : nv_(m->nv) {
  const size_t rows = static_cast<size_t>(max_rows);
  A_.resize(rows * rows);
  L_.resize(rows * rows);
  Js_.resize(rows * nv_);
  X_.resize(rows * nv_);
  column_slot_.assign(nv_, -1);
  support_.assign(kMaxLowRank, 0);
  Y_.resize(static_cast<size_t>(kMaxLowRank) * nv_);
  P_.resize(kMaxLowRank * kMaxLowRank);
  Pinv_.resize(kMaxLowRank * kMaxLowRank);
  Jc_.resize(rows * kMaxLowRank);
  Z_.resize(rows * kMaxLowRank);
  U_.resize(rows * kMaxRigid);
  scratch_.resize(rows);
}

void Delassus::Build(const mjModel* m, mjData* d, const FrictionRows& rows) {
  n_ = rows.n;
  if (!BuildLowRank(m, d, rows)) BuildDense(m, d, rows);
}

bool Delassus::BuildLowRank(const mjModel* m, mjData* d, const FrictionRows& rows) {
  // The columns the rows touch; worth it only while they are few against the rows.
  low_rank_ = false;
  k_ = 0;
  for (int c = 0; c < nv_; ++c) column_slot_[c] = -1;
  for (int r = 0; r < n_; ++r) {
    const int* cols = rows.col.data() + static_cast<size_t>(r) * rows.stride;
    for (int t = 0; t < rows.count[r]; ++t) {
      if (column_slot_[cols[t]] >= 0) continue;
      if (k_ >= kMaxLowRank || 2 * (k_ + 1) > n_) return false;
      column_slot_[cols[t]] = k_;
      support_[k_++] = cols[t];
    }
  }
  // P = ((M + h B)^-1)_CC, one solve per column.
  std::fill(X_.begin(), X_.begin() + static_cast<size_t>(k_) * nv_, 0.0);
  for (int a = 0; a < k_; ++a) X_[static_cast<size_t>(a) * nv_ + support_[a]] = 1.0;
  mj_solveM(m, d, Y_.data(), X_.data(), k_);
  for (int a = 0; a < k_; ++a) {
    for (int b = 0; b < k_; ++b) P_[a * k_ + b] = Y_[static_cast<size_t>(a) * nv_ + support_[b]];
  }
  // Compact rows J_C and Z = J_C P (A = Z J_C' is never formed: A f = Z (J_C' f)).
  for (int r = 0; r < n_; ++r) {
    double* jc = Jc_.data() + static_cast<size_t>(r) * k_;
    std::fill(jc, jc + k_, 0.0);
    const int* cols = rows.col.data() + static_cast<size_t>(r) * rows.stride;
    const double* vals = rows.val.data() + static_cast<size_t>(r) * rows.stride;
    for (int t = 0; t < rows.count[r]; ++t) jc[column_slot_[cols[t]]] = vals[t];
    double* z = Z_.data() + static_cast<size_t>(r) * k_;
    for (int b = 0; b < k_; ++b) {
      double acc = 0.0;
      for (int a = 0; a < k_; ++a) acc += jc[a] * P_[a * k_ + b];
      z[b] = acc;
    }
  }
  // P^-1 for the Woodbury solve.
  double chol[kMaxLowRank * kMaxLowRank];
  std::copy(P_.begin(), P_.begin() + k_ * k_, chol);
  mju_cholFactor(chol, k_, 0.0);
  for (int a = 0; a < k_; ++a) {
    double e[kMaxLowRank] = {0};
    e[a] = 1.0;
    mju_cholSolve(e, chol, e, k_);
    for (int b = 0; b < k_; ++b) Pinv_[a * k_ + b] = e[b];
  }
  low_rank_ = true;
  return true;
}

void Delassus::BuildDense(const mjModel* m, mjData* d, const FrictionRows& rows) {
  // X = (M + h B)^-1 J', one solve per row, and A = J X'.
  std::fill(Js_.begin(), Js_.begin() + static_cast<size_t>(n_) * nv_, 0.0);
  for (int r = 0; r < n_; ++r) {
    double* js = Js_.data() + static_cast<size_t>(r) * nv_;
    const int* cols = rows.col.data() + static_cast<size_t>(r) * rows.stride;
    const double* vals = rows.val.data() + static_cast<size_t>(r) * rows.stride;
    for (int t = 0; t < rows.count[r]; ++t) js[cols[t]] = vals[t];
  }
  mj_solveM(m, d, X_.data(), Js_.data(), n_);
  for (int r = 0; r < n_; ++r) {
    const int* cols = rows.col.data() + static_cast<size_t>(r) * rows.stride;
    const double* vals = rows.val.data() + static_cast<size_t>(r) * rows.stride;
    for (int l = 0; l <= r; ++l) {
      const double* xl = X_.data() + static_cast<size_t>(l) * nv_;
      double acc = 0.0;
      for (int t = 0; t < rows.count[r]; ++t) acc += vals[t] * xl[cols[t]];
      A_[static_cast<size_t>(r) * n_ + l] = A_[static_cast<size_t>(l) * n_ + r] = acc;
    }
  }
}

double Delassus::At(int r, int l) const {
  if (!low_rank_) return A_[static_cast<size_t>(r) * n_ + l];
  const double* z = Z_.data() + static_cast<size_t>(r) * k_;
  const double* jl = Jc_.data() + static_cast<size_t>(l) * k_;
  double acc = 0.0;
  for (int a = 0; a < k_; ++a) acc += z[a] * jl[a];
  return acc;
}

void Delassus::Multiply(const double* f, const char* mask, double* out) const {
  if (low_rank_) {
    double g[kMaxLowRank] = {0};
    for (int l = 0; l < n_; ++l) {
      if (mask && !mask[l]) continue;
      const double* jl = Jc_.data() + static_cast<size_t>(l) * k_;
      for (int a = 0; a < k_; ++a) g[a] += jl[a] * f[l];
    }
    for (int r = 0; r < n_; ++r) {
      const double* z = Z_.data() + static_cast<size_t>(r) * k_;
      double acc = 0.0;
      for (int a = 0; a < k_; ++a) acc += z[a] * g[a];
      out[r] = acc;
    }
    return;
  }
  for (int r = 0; r < n_; ++r) {
    const double* ar = A_.data() + static_cast<size_t>(r) * n_;
    double acc = 0.0;
    for (int l = 0; l < n_; ++l) {
      if (!mask || mask[l]) acc += ar[l] * f[l];
    }
    out[r] = acc;
  }
}

void Delassus::Track(const double* f) {
  tracked_f_ = f;
  if (!low_rank_) return;
  std::fill(tracked_, tracked_ + k_, 0.0);
  for (int l = 0; l < n_; ++l) {
    const double* jl = Jc_.data() + static_cast<size_t>(l) * k_;
    for (int a = 0; a < k_; ++a) tracked_[a] += jl[a] * f[l];
  }
}

double Delassus::RowTimesTracked(int r) const {
  double acc = 0.0;
  if (low_rank_) {
    const double* z = Z_.data() + static_cast<size_t>(r) * k_;
    for (int a = 0; a < k_; ++a) acc += z[a] * tracked_[a];
    return acc;
  }
  const double* ar = A_.data() + static_cast<size_t>(r) * n_;
  for (int l = 0; l < n_; ++l) acc += ar[l] * tracked_f_[l];
  return acc;
}

void Delassus::Change(int l, double delta) {
  if (!low_rank_) return;  // the dense form reads the forces themselves
  const double* jl = Jc_.data() + static_cast<size_t>(l) * k_;
  for (int a = 0; a < k_; ++a) tracked_[a] += jl[a] * delta;
}

void Delassus::SolveFree(int ns, const int* free, const double* reg, const double* capacity, const double* rhs,
                         double* x) {
  int rigid = 0;
  for (int a = 0; a < ns; ++a) rigid += reg[free[a]] > 0.0 ? 0 : 1;
  if (low_rank_ && rigid <= kMaxRigid) {
    SolveWoodbury(ns, free, reg, capacity, rhs, x);
  } else {
    SolveDense(ns, free, reg, capacity, rhs, x);
  }
}

double Delassus::RigidWeight(int ns, const int* free, const double* capacity, int k) const {
  double max_diag = 0.0, max_cap = kMinCapacity;
  for (int a = 0; a < ns; ++a) {
    max_diag = std::max(max_diag, At(free[a], free[a]));
    max_cap = std::max(max_cap, capacity[free[a]]);
  }
  const double eps = kRigidRowRegularization * std::max(max_diag, 1e-300);
  const double cap = std::max(capacity[k], kMinCapacity) / max_cap;
  return eps / (cap * cap);
}

void Delassus::FactorCompliant(int ns, const int* free, const double* reg) {
  // P^-1 + W' R^-1 W over the compliant free rows, W = their J_C.
  std::copy(Pinv_.begin(), Pinv_.begin() + k_ * k_, woodbury_);
  for (int a = 0; a < ns; ++a) {
    const int r = free[a];
    if (reg[r] <= 0.0) continue;
    const double* w = Jc_.data() + static_cast<size_t>(r) * k_;
    const double rinv = 1.0 / reg[r];
    for (int i = 0; i < k_; ++i) {
      for (int j = 0; j <= i; ++j) woodbury_[i * k_ + j] += w[i] * rinv * w[j];
    }
  }
  for (int i = 0; i < k_; ++i) {
    for (int j = 0; j < i; ++j) woodbury_[j * k_ + i] = woodbury_[i * k_ + j];
  }
  mju_cholFactor(woodbury_, k_, 0.0);
}

void Delassus::CompliantSolve(int ns, const int* free, const double* reg, const double* in, double* out) const {
  // out = (A_SS + R_S)^-1 in over the compliant free rows (rigid positions: 0), by
  // R^-1 - R^-1 W (P^-1 + W' R^-1 W)^-1 W' R^-1.
  double y[kMaxLowRank] = {0};
  for (int a = 0; a < ns; ++a) {
    const int r = free[a];
    out[a] = reg[r] > 0.0 ? in[a] / reg[r] : 0.0;
    const double* w = Jc_.data() + static_cast<size_t>(r) * k_;
    for (int i = 0; i < k_; ++i) y[i] += w[i] * out[a];
  }
  mju_cholSolve(y, woodbury_, y, k_);
  for (int a = 0; a < ns; ++a) {
    const int r = free[a];
    if (reg[r] <= 0.0) continue;
    const double* w = Jc_.data() + static_cast<size_t>(r) * k_;
    double wy = 0.0;
    for (int i = 0; i < k_; ++i) wy += w[i] * y[i];
    out[a] -= wy / reg[r];
  }
}

double Delassus::RowTimes(int ns, const int* free, const double* reg, int row, const double* x) const {
  // sum over the compliant free rows a of A(row, a) x_a.
  double g[kMaxLowRank] = {0};
  for (int a = 0; a < ns; ++a) {
    if (reg[free[a]] <= 0.0 || x[a] == 0.0) continue;
    const double* w = Jc_.data() + static_cast<size_t>(free[a]) * k_;
    for (int i = 0; i < k_; ++i) g[i] += w[i] * x[a];
  }
  const double* z = Z_.data() + static_cast<size_t>(row) * k_;
  double acc = 0.0;
  for (int i = 0; i < k_; ++i) acc += z[i] * g[i];
  return acc;
}

void Delassus::SolveWoodbury(int ns, const int* free, const double* reg, const double* capacity, const double* rhs,
                             double* x) {
  // Compliant free rows S by Woodbury, the rigid ones T by their Schur complement:
  // f_T = (A_TT + E - A_TS U)^-1 (r_T - A_TS y), f_S = y - U f_T, with y = (A_SS + R_S)^-1 r_S
  // and U = (A_SS + R_S)^-1 A_ST.
  FactorCompliant(ns, free, reg);
  int rigid[kMaxRigid], nt = 0;
  for (int a = 0; a < ns; ++a) {
    if (reg[free[a]] <= 0.0) rigid[nt++] = a;
  }
  CompliantSolve(ns, free, reg, rhs, x);
  if (nt == 0) return;
  double schur[kMaxRigid * kMaxRigid], rt[kMaxRigid];
  for (int j = 0; j < nt; ++j) {
    const int tj = free[rigid[j]];
    for (int a = 0; a < ns; ++a) scratch_[a] = reg[free[a]] > 0.0 ? At(free[a], tj) : 0.0;
    CompliantSolve(ns, free, reg, scratch_.data(), U_.data() + static_cast<size_t>(j) * n_);
  }
  for (int i = 0; i < nt; ++i) {
    const int ti = free[rigid[i]];
    rt[i] = rhs[rigid[i]] - RowTimes(ns, free, reg, ti, x);
    for (int j = 0; j < nt; ++j) {
      schur[i * nt + j] = At(ti, free[rigid[j]]) - RowTimes(ns, free, reg, ti, U_.data() + static_cast<size_t>(j) * n_);
    }
    schur[i * nt + i] += RigidWeight(ns, free, capacity, ti);
  }
  for (int i = 0; i < nt; ++i) {  // symmetric against round-off
    for (int j = 0; j < i; ++j) schur[i * nt + j] = schur[j * nt + i] = 0.5 * (schur[i * nt + j] + schur[j * nt + i]);
  }
  mju_cholFactor(schur, nt, 0.0);
  mju_cholSolve(rt, schur, rt, nt);
  for (int j = 0; j < nt; ++j) {
    const double* u = U_.data() + static_cast<size_t>(j) * n_;
    for (int a = 0; a < ns; ++a) x[a] -= u[a] * rt[j];
    x[rigid[j]] = rt[j];
  }
}

void Delassus::SolveDense(int ns, const int* free, const double* reg, const double* capacity, const double* rhs,
                          double* x) {
  // Cholesky of A_SS + R_S (+ the rigid rows' weights).
  double max_diag = 0.0, max_cap = kMinCapacity;
  for (int a = 0; a < ns; ++a) {
    max_diag = std::max(max_diag, At(free[a], free[a]));
    max_cap = std::max(max_cap, capacity[free[a]]);
  }
  const double eps = kRigidRowRegularization * std::max(max_diag, 1e-300);
  for (int a = 0; a < ns; ++a) {
    const int k = free[a];
    for (int b = 0; b <= a; ++b) {
      L_[static_cast<size_t>(a) * ns + b] = L_[static_cast<size_t>(b) * ns + a] = At(k, free[b]);
    }
    const double cap = std::max(capacity[k], kMinCapacity) / max_cap;
    L_[static_cast<size_t>(a) * ns + a] += reg[k] + (reg[k] > 0.0 ? 0.0 : eps / (cap * cap));
    x[a] = rhs[a];
  }
  mju_cholFactor(L_.data(), ns, 1e-6 * eps);
  mju_cholSolve(x, L_.data(), x, ns);
}

}  // namespace tactip
