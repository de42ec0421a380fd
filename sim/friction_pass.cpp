#include "sim/friction_pass.h"

#include <mujoco/mujoco.h>

#include <algorithm>
#include <cmath>

namespace tactip {

namespace {
constexpr double kRegularization = 1e-9;  // rigid rows: relative to A's largest diagonal (picks the least-loaded solution)
constexpr double kMinCapacity = 1e-9;     // N: friction capacity floor in those weights
constexpr double kConeTolerance = 1e-9;   // relative excess over the cone before a contact is clamped

std::uint64_t PairKey(const mjContact& con) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(con.geom1)) << 32) |
         static_cast<std::uint32_t>(con.geom2);
}

double Dot3(const double* a, const double* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

}  // namespace

FrictionPass::FrictionPass(const mjModel* m, const FrictionPassSettings& settings)
    : settings_(settings), nv_(m->nv) {
  const size_t rows = static_cast<size_t>(m->njmax);
  for (auto* v : {&row_, &contact_, &group_size_, &nz_count_, &free_}) v->resize(rows);
  for (auto* v : {&limit_, &mu_, &reg_, &spring_, &disp_, &stiff_, &target_, &f0_, &f_, &rhs_, &x_, &af_,
                  &rhs_scratch_}) {
    v->resize(rows);
  }
  clamped_.resize(rows);
  for (auto* v : {&Js_, &X_}) v->resize(rows * nv_);
  nz_col_.resize(rows * nv_);
  nz_val_.resize(rows * nv_);
  A_.resize(rows * rows);
  L_.resize(rows * rows);
  qfrc_.resize(nv_);
  qacc0_.resize(nv_);
  qfrc_nf_.resize(nv_);
  sticks_.reserve(static_cast<size_t>(m->nconmax) + 1);
  dof_sliding_.assign(nv_, 0);
  column_slot_.assign(nv_, -1);
  support_.assign(kMaxLowRank, 0);
  Y_.resize(static_cast<size_t>(kMaxLowRank) * nv_);
  for (auto* v : {&P_, &Pchol_, &Pinv_}) v->resize(kMaxLowRank * kMaxLowRank);
  Jc_.resize(rows * kMaxLowRank);
  Z_.resize(rows * kMaxLowRank);
  U_.resize(rows * kMaxRigid);
}

int FrictionPass::CollectRows(const mjModel* m, mjData* d) {
  // Friction rows of every elliptic contact that pushes (its normal force fixed as the
  // cone's size) and every dry-friction row (its frictionloss as the box). Contacts that
  // do not push carry no friction.
  int n = 0;
  for (int i = 0; i < d->nefc; ++i) {
    const int type = d->efc_type[i];
    if (type == mjCNSTR_FRICTION_DOF || type == mjCNSTR_FRICTION_TENDON) {
      row_[n] = i, contact_[n] = -1, group_size_[n] = 1, limit_[n] = d->efc_frictionloss[i], mu_[n] = 1.0;
      ++n;
      continue;
    }
    if (type != mjCNSTR_CONTACT_ELLIPTIC) continue;
    const mjContact& con = d->contact[d->efc_id[i]];
    const double fn = d->efc_force[i];
    for (int j = 1; j < con.dim; ++j) {
      if (fn <= 0.0) {
        d->efc_force[i + j] = 0.0;
        continue;
      }
      row_[n] = i + j, contact_[n] = d->efc_id[i], group_size_[n] = con.dim - 1, limit_[n] = fn;
      mu_[n] = con.friction[j - 1];
      ++n;
    }
    i += con.dim - 1;
  }
  (void)m;
  return n;
}

void FrictionPass::BuildSystem(const mjModel* m, mjData* d) {
  // Friction rows as sparse rows (non-zero columns and values), the stick velocity
  // v = J qvel, and the rigid-stick right-hand side -(v / h + J qacc_nf), qacc_nf being the
  // integrator's acceleration with every constraint force but friction (qfrc_nf, kept for
  // WriteBack). Then the Delassus operator A = J (M + h B)^-1 J', low-rank when it can be.
  const bool sparse = mj_isSparse(m);
  const double h = m->opt.timestep;
  for (int c = 0; c < nv_; ++c) qfrc_nf_[c] = d->qfrc_constraint[c];
  for (int k = 0; k < n_; ++k) {
    const int i = row_[k];
    const double f0 = d->efc_force[i];
    int* cols = nz_col_.data() + static_cast<size_t>(k) * nv_;
    double* vals = nz_val_.data() + static_cast<size_t>(k) * nv_;
    int nz = 0;
    const auto take = [&](int c, double jv) {
      qfrc_nf_[c] -= jv * f0;  // take the main solver's friction out
      if (jv == 0.0) return;
      cols[nz] = c;
      vals[nz++] = jv;
    };
    if (sparse) {
      const int adr = d->efc_J_rowadr[i];
      for (int t = 0; t < d->efc_J_rownnz[i]; ++t) take(d->efc_J_colind[adr + t], d->efc_J[adr + t]);
    } else {
      for (int c = 0; c < nv_; ++c) take(c, d->efc_J[static_cast<size_t>(i) * nv_ + c]);
    }
    nz_count_[k] = nz;
    f0_[k] = f_[k] = f0;
    clamped_[k] = 0;
  }
  for (int c = 0; c < nv_; ++c) qfrc_[c] = d->qfrc_smooth[c] + qfrc_nf_[c];
  mj_solveM(m, d, qacc0_.data(), qfrc_.data(), 1);
  for (int k = 0; k < n_; ++k) {
    const int* cols = nz_col_.data() + static_cast<size_t>(k) * nv_;
    const double* vals = nz_val_.data() + static_cast<size_t>(k) * nv_;
    double v = 0.0, a = 0.0;
    for (int t = 0; t < nz_count_[k]; ++t) {
      v += vals[t] * d->qvel[cols[t]];
      a += vals[t] * qacc0_[cols[t]];
    }
    target_[k] = -v / h - a;
  }
  if (!LowRankDelassus(m, d)) DenseDelassus(m, d);
}

double FrictionPass::Arl(int r, int l) const {
  if (!low_rank_) return A_[static_cast<size_t>(r) * n_ + l];
  const double* z = Z_.data() + static_cast<size_t>(r) * k_;
  const double* jl = Jc_.data() + static_cast<size_t>(l) * k_;
  double acc = 0.0;
  for (int a = 0; a < k_; ++a) acc += z[a] * jl[a];
  return acc;
}

void FrictionPass::MulA(bool clamped_only, double* out) const {
  // out = A f over all rows, or over the clamped rows only.
  if (low_rank_) {
    double g[kMaxLowRank] = {0};
    for (int l = 0; l < n_; ++l) {
      if (clamped_only && !clamped_[l]) continue;
      const double* jl = Jc_.data() + static_cast<size_t>(l) * k_;
      for (int a = 0; a < k_; ++a) g[a] += jl[a] * f_[l];
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
      if (!clamped_only || clamped_[l]) acc += ar[l] * f_[l];
    }
    out[r] = acc;
  }
}

bool FrictionPass::LowRankDelassus(const mjModel* m, mjData* d) {
  // The friction rows usually touch only a few dofs (the shared bodies: skin shell, arm,
  // object): with C those columns, A = J_C P J_C' where P = ((M + h B)^-1)_CC needs one
  // solve per column instead of one per row.
  k_ = 0;
  for (int c = 0; c < nv_; ++c) column_slot_[c] = -1;
  for (int r = 0; r < n_; ++r) {
    const int* cols = nz_col_.data() + static_cast<size_t>(r) * nv_;
    for (int t = 0; t < nz_count_[r]; ++t) {
      if (column_slot_[cols[t]] >= 0) continue;
      if (k_ >= kMaxLowRank || 2 * (k_ + 1) > n_) return false;
      column_slot_[cols[t]] = k_;
      support_[k_++] = cols[t];
    }
  }
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
    const int* cols = nz_col_.data() + static_cast<size_t>(r) * nv_;
    const double* vals = nz_val_.data() + static_cast<size_t>(r) * nv_;
    for (int t = 0; t < nz_count_[r]; ++t) jc[column_slot_[cols[t]]] = vals[t];
    double* z = Z_.data() + static_cast<size_t>(r) * k_;
    for (int b = 0; b < k_; ++b) {
      double acc = 0.0;
      for (int a = 0; a < k_; ++a) acc += jc[a] * P_[a * k_ + b];
      z[b] = acc;
    }
  }
  // P^-1 for the Woodbury solve.
  std::copy(P_.begin(), P_.begin() + k_ * k_, Pchol_.begin());
  mju_cholFactor(Pchol_.data(), k_, 0.0);
  for (int a = 0; a < k_; ++a) {
    double e[kMaxLowRank] = {0};
    e[a] = 1.0;
    mju_cholSolve(e, Pchol_.data(), e, k_);
    for (int b = 0; b < k_; ++b) Pinv_[a * k_ + b] = e[b];
  }
  low_rank_ = true;
  return true;
}

void FrictionPass::DenseDelassus(const mjModel* m, mjData* d) {
  // X = (M + h B)^-1 J', one solve per row, and A = J X'.
  low_rank_ = false;
  std::fill(Js_.begin(), Js_.begin() + static_cast<size_t>(n_) * nv_, 0.0);
  for (int r = 0; r < n_; ++r) {
    double* js = Js_.data() + static_cast<size_t>(r) * nv_;
    const int* cols = nz_col_.data() + static_cast<size_t>(r) * nv_;
    const double* vals = nz_val_.data() + static_cast<size_t>(r) * nv_;
    for (int t = 0; t < nz_count_[r]; ++t) js[cols[t]] = vals[t];
  }
  mj_solveM(m, d, X_.data(), Js_.data(), n_);
  for (int r = 0; r < n_; ++r) {
    const int* cols = nz_col_.data() + static_cast<size_t>(r) * nv_;
    const double* vals = nz_val_.data() + static_cast<size_t>(r) * nv_;
    for (int l = 0; l <= r; ++l) {
      const double* xl = X_.data() + static_cast<size_t>(l) * nv_;
      double acc = 0.0;
      for (int t = 0; t < nz_count_[r]; ++t) acc += vals[t] * xl[cols[t]];
      A_[static_cast<size_t>(r) * n_ + l] = A_[static_cast<size_t>(l) * n_ + r] = acc;
    }
  }
}

FrictionPass::Stick* FrictionPass::FindStick(std::uint64_t key) {
  auto it = std::lower_bound(sticks_.begin(), sticks_.end(), key,
                             [](const Stick& a, std::uint64_t k) { return a.key < k; });
  return it != sticks_.end() && it->key == key ? &*it : nullptr;
}

void FrictionPass::ContactSprings(const mjModel* m, const mjData* d) {
  // Per contact row: displacement s since the contact stuck, along the row's tangent; the
  // stiffness K = mu N / delta, damping C = K h, and the backward-Euler regularization
  // R = 1 / (h (K h + C)) with the spring's pull R K s. Rigid stick (delta = 0, torsion
  // and rolling rows, dry friction): R = 0 and the pull s / h^2 closes the gap in one step.
  const double h = m->opt.timestep;
  const double delta = settings_.presliding_m;
  for (auto& s : sticks_) s.seen = false;
  for (int k = 0; k < n_; k += group_size_[k]) {
    const int c = contact_[k];
    for (int j = 0; j < group_size_[k]; ++j) reg_[k + j] = spring_[k + j] = disp_[k + j] = stiff_[k + j] = 0.0;
    if (c < 0) continue;  // dry friction sticks rigidly
    const mjContact& con = d->contact[c];
    const std::uint64_t key = PairKey(con);
    Stick* st = FindStick(key);
    if (!st) {
      Stick fresh;
      fresh.key = key;
      auto it = std::lower_bound(sticks_.begin(), sticks_.end(), key,
                                 [](const Stick& a, std::uint64_t kk) { return a.key < kk; });
      st = &*sticks_.insert(it, fresh);
    }
    st->seen = true;
    if (limit_[k] > st->normal_N) {
      // Loading: the new share of the contact starts unstretched.
      const double keep = st->normal_N / limit_[k];
      for (double& x : st->s) x *= keep;
    }
    st->normal_N = limit_[k];
    for (int j = 0; j < group_size_[k]; ++j) {
      const int r = k + j;
      const double s = j < 2 ? Dot3(con.frame + 3 * (j + 1), st->s) : 0.0;
      disp_[r] = s;
      if (delta <= 0.0 || j >= 2) {
        spring_[r] = s / (h * h);
        continue;
      }
      const double K = mu_[r] * limit_[r] / delta;
      const double C = K * h;  // damping time one step: dynamic forces stay in proportion to N too
      stiff_[r] = K;
      reg_[r] = 1.0 / (h * (K * h + C));
      spring_[r] = reg_[r] * K * s;
    }
  }
}

int FrictionPass::DryDof(const mjData* d, int k) const {
  const int i = row_[k];
  return d->efc_type[i] == mjCNSTR_FRICTION_DOF ? d->efc_id[i] : -1;
}

void FrictionPass::StartFromLastState(const mjData* d) {
  // Groups that were sliding at the end of the last step start clamped, their force on
  // the limit along the main solver's direction; UpdateClampedGroups releases them if
  // they can stick now.
  for (int k = 0; k < n_; k += group_size_[k]) {
    bool sliding = false;
    if (contact_[k] < 0) {
      const int dof = DryDof(d, k);
      sliding = dof >= 0 && dof_sliding_[dof];
    } else {
      const Stick* st = FindStick(PairKey(d->contact[contact_[k]]));
      sliding = st && st->sliding;
    }
    if (!sliding) continue;
    double norm = 0.0;
    for (int j = 0; j < group_size_[k]; ++j) norm += f0_[k + j] * f0_[k + j] / (mu_[k + j] * mu_[k + j]);
    const double scale = norm > 0.0 ? limit_[k] / std::sqrt(norm) : 0.0;
    for (int j = 0; j < group_size_[k]; ++j) {
      f_[k + j] = f0_[k + j] * scale;
      clamped_[k + j] = 1;
    }
  }
}

void FrictionPass::SolveFree() {
  // Free rows S, clamped rows C held at f_C: (A_SS + R_S) f_S = target_S - pull_S - A_SC f_C.
  int ns = 0, rigid = 0;
  for (int k = 0; k < n_; ++k) {
    if (clamped_[k]) continue;
    free_[ns++] = k;
    rigid += reg_[k] > 0.0 ? 0 : 1;
  }
  if (ns == 0) return;
  MulA(true, af_.data());
  for (int a = 0; a < ns; ++a) rhs_[a] = target_[free_[a]] - spring_[free_[a]] - af_[free_[a]];
  if (low_rank_ && rigid <= kMaxRigid) {
    SolveWoodbury(ns);
  } else {
    SolveDense(ns);
  }
  for (int a = 0; a < ns; ++a) f_[free_[a]] = x_[a];
}

double FrictionPass::RigidWeight(int ns, int k) const {
  // The tiny diagonal weight of a rigid row (see SolveDense).
  double max_diag = 0.0, max_cap = kMinCapacity;
  for (int a = 0; a < ns; ++a) {
    max_diag = std::max(max_diag, Arl(free_[a], free_[a]));
    max_cap = std::max(max_cap, mu_[free_[a]] * limit_[free_[a]]);
  }
  const double eps = kRegularization * std::max(max_diag, 1e-300);
  const double cap = std::max(mu_[k] * limit_[k], kMinCapacity) / max_cap;
  return eps / (cap * cap);
}

void FrictionPass::FactorCompliant(int ns) {
  // Woodbury: (R + W P W')^-1 = R^-1 - R^-1 W (P^-1 + W' R^-1 W)^-1 W' R^-1 over the
  // compliant free rows, W = their J_C: a k x k factor instead of an ns x ns one.
  std::copy(Pinv_.begin(), Pinv_.begin() + k_ * k_, woodbury_);
  for (int a = 0; a < ns; ++a) {
    const int r = free_[a];
    if (reg_[r] <= 0.0) continue;
    const double* w = Jc_.data() + static_cast<size_t>(r) * k_;
    const double rinv = 1.0 / reg_[r];
    for (int i = 0; i < k_; ++i) {
      for (int j = 0; j <= i; ++j) woodbury_[i * k_ + j] += w[i] * rinv * w[j];
    }
  }
  for (int i = 0; i < k_; ++i) {
    for (int j = 0; j < i; ++j) woodbury_[j * k_ + i] = woodbury_[i * k_ + j];
  }
  mju_cholFactor(woodbury_, k_, 0.0);
}

void FrictionPass::CompliantSolve(int ns, const double* in, double* out) const {
  // out = (A_SS + R_S)^-1 in over the compliant free rows (rigid positions: 0).
  double y[kMaxLowRank] = {0};
  for (int a = 0; a < ns; ++a) {
    const int r = free_[a];
    out[a] = reg_[r] > 0.0 ? in[a] / reg_[r] : 0.0;
    const double* w = Jc_.data() + static_cast<size_t>(r) * k_;
    for (int i = 0; i < k_; ++i) y[i] += w[i] * out[a];
  }
  mju_cholSolve(y, woodbury_, y, k_);
  for (int a = 0; a < ns; ++a) {
    const int r = free_[a];
    if (reg_[r] <= 0.0) continue;
    const double* w = Jc_.data() + static_cast<size_t>(r) * k_;
    double wy = 0.0;
    for (int i = 0; i < k_; ++i) wy += w[i] * y[i];
    out[a] -= wy / reg_[r];
  }
}

double FrictionPass::RowTimes(int ns, int row, const double* x) const {
  // sum over the compliant free rows a of A(row, a) x_a, through the low-rank form.
  double g[kMaxLowRank] = {0};
  for (int a = 0; a < ns; ++a) {
    if (reg_[free_[a]] <= 0.0 || x[a] == 0.0) continue;
    const double* w = Jc_.data() + static_cast<size_t>(free_[a]) * k_;
    for (int i = 0; i < k_; ++i) g[i] += w[i] * x[a];
  }
  const double* z = Z_.data() + static_cast<size_t>(row) * k_;
  double acc = 0.0;
  for (int i = 0; i < k_; ++i) acc += z[i] * g[i];
  return acc;
}

void FrictionPass::SolveWoodbury(int ns) {
  // Compliant free rows S by Woodbury, the few rigid ones T by their Schur complement:
  // f_T = (A_TT + E - A_TS U)^-1 (r_T - A_TS y), f_S = y - U f_T, with y = (A_SS + R_S)^-1 r_S
  // and U = (A_SS + R_S)^-1 A_ST.
  FactorCompliant(ns);
  int rigid[kMaxRigid], nt = 0;
  for (int a = 0; a < ns; ++a) {
    if (reg_[free_[a]] <= 0.0) rigid[nt++] = a;
  }
  CompliantSolve(ns, rhs_.data(), x_.data());
  if (nt == 0) return;
  double schur[kMaxRigid * kMaxRigid], rt[kMaxRigid];
  for (int j = 0; j < nt; ++j) {
    const int tj = free_[rigid[j]];
    double* u = U_.data() + static_cast<size_t>(j) * n_;
    for (int a = 0; a < ns; ++a) rhs_scratch_[a] = reg_[free_[a]] > 0.0 ? Arl(free_[a], tj) : 0.0;
    CompliantSolve(ns, rhs_scratch_.data(), u);
  }
  for (int i = 0; i < nt; ++i) {
    const int ti = free_[rigid[i]];
    rt[i] = rhs_[rigid[i]] - RowTimes(ns, ti, x_.data());
    for (int j = 0; j < nt; ++j) {
      const double* u = U_.data() + static_cast<size_t>(j) * n_;
      schur[i * nt + j] = Arl(ti, free_[rigid[j]]) - RowTimes(ns, ti, u);
    }
    schur[i * nt + i] += RigidWeight(ns, ti);
  }
  for (int i = 0; i < nt; ++i) {  // symmetrize against round-off
    for (int j = 0; j < i; ++j) schur[i * nt + j] = schur[j * nt + i] = 0.5 * (schur[i * nt + j] + schur[j * nt + i]);
  }
  mju_cholFactor(schur, nt, 0.0);
  mju_cholSolve(rt, schur, rt, nt);
  for (int j = 0; j < nt; ++j) {
    const double* u = U_.data() + static_cast<size_t>(j) * n_;
    for (int a = 0; a < ns; ++a) x_[a] -= u[a] * rt[j];
    x_[rigid[j]] = rt[j];
  }
}

void FrictionPass::SolveDense(int ns) {
  // Cholesky of A_SS + R_S. Rigid rows that share bodies make A_SS singular (internal
  // forces between them move nothing); among their solutions the one taken loads each
  // contact in proportion to its capacity (minimum sum f^2 / (mu N)^2), through a tiny
  // weight on the diagonal.
  double max_diag = 0.0, max_cap = kMinCapacity;
  for (int a = 0; a < ns; ++a) {
    const int k = free_[a];
    max_diag = std::max(max_diag, Arl(k, k));
    max_cap = std::max(max_cap, mu_[k] * limit_[k]);
  }
  const double eps = kRegularization * std::max(max_diag, 1e-300);
  for (int a = 0; a < ns; ++a) {
    const int k = free_[a];
    for (int b = 0; b <= a; ++b) {
      L_[static_cast<size_t>(a) * ns + b] = L_[static_cast<size_t>(b) * ns + a] = Arl(k, free_[b]);
    }
    const double cap = std::max(mu_[k] * limit_[k], kMinCapacity) / max_cap;
    L_[static_cast<size_t>(a) * ns + a] += reg_[k] + (reg_[k] > 0.0 ? 0.0 : eps / (cap * cap));
    x_[a] = rhs_[a];
  }
  mju_cholFactor(L_.data(), ns, 1e-6 * eps);
  mju_cholSolve(x_.data(), L_.data(), x_.data(), ns);
}

int FrictionPass::UpdateClampedGroups() {
  // Each clamped group's force is put where it would stick given all the others (their
  // latest forces), then back onto its limit along that direction; a group whose sticking
  // force lies inside its limit is released.
  int released = 0;
  double M[25], x[5];
  if (low_rank_) GatherForces();
  for (int k = 0; k < n_; k += group_size_[k]) {
    if (!clamped_[k]) continue;
    const int g = group_size_[k];
    for (int a = 0; a < g; ++a) {
      double r = target_[k + a] - spring_[k + a] - RowTimesForces(k + a);
      for (int c = 0; c < g; ++c) {
        M[a * g + c] = Arl(k + a, k + c);
        r += M[a * g + c] * f_[k + c];
      }
      x[a] = r;
      M[a * g + a] += reg_[k + a] + kRegularization * std::max(M[a * g + a], 1e-300);
    }
    mju_cholFactor(M, g, 1e-300);
    mju_cholSolve(x, M, x, g);
    double norm = 0.0;
    for (int a = 0; a < g; ++a) norm += x[a] * x[a] / (mu_[k + a] * mu_[k + a]);
    const bool inside = norm <= limit_[k] * limit_[k];
    const double scale = inside || norm <= 0.0 ? 1.0 : limit_[k] / std::sqrt(norm);
    for (int a = 0; a < g; ++a) {
      SetForce(k + a, x[a] * scale);
      if (inside) clamped_[k + a] = 0;
    }
    released += inside ? 1 : 0;
  }
  return released;
}

void FrictionPass::GatherForces() {
  // g = J_C' f: A f = Z g in the low-rank form.
  std::fill(gathered_, gathered_ + k_, 0.0);
  for (int l = 0; l < n_; ++l) {
    const double* jl = Jc_.data() + static_cast<size_t>(l) * k_;
    for (int a = 0; a < k_; ++a) gathered_[a] += jl[a] * f_[l];
  }
}

double FrictionPass::RowTimesForces(int r) const {
  // (A f)_r with the latest forces (low rank: needs GatherForces and SetForce).
  double acc = 0.0;
  if (low_rank_) {
    const double* z = Z_.data() + static_cast<size_t>(r) * k_;
    for (int a = 0; a < k_; ++a) acc += z[a] * gathered_[a];
    return acc;
  }
  const double* ar = A_.data() + static_cast<size_t>(r) * n_;
  for (int l = 0; l < n_; ++l) acc += ar[l] * f_[l];
  return acc;
}

void FrictionPass::SetForce(int l, double f) {
  if (low_rank_) {
    const double* jl = Jc_.data() + static_cast<size_t>(l) * k_;
    for (int a = 0; a < k_; ++a) gathered_[a] += jl[a] * (f - f_[l]);
  }
  f_[l] = f;
}

int FrictionPass::ClampOutsideLimits() {
  // A free group outside its cone (|f|_mu > N) or box (|f| > frictionloss) is put on the
  // boundary along its unconstrained direction and held there: it slides.
  int added = 0;
  for (int k = 0; k < n_; k += group_size_[k]) {
    if (clamped_[k]) continue;
    double s = 0.0;
    for (int j = 0; j < group_size_[k]; ++j) s += f_[k + j] * f_[k + j] / (mu_[k + j] * mu_[k + j]);
    const double lim = limit_[k];
    if (s <= lim * lim * (1.0 + kConeTolerance)) continue;
    const double scale = lim / std::sqrt(s);
    for (int j = 0; j < group_size_[k]; ++j) {
      f_[k + j] *= scale;
      clamped_[k + j] = 1;
    }
    ++added;
  }
  return added;
}

void FrictionPass::SaveState(const mjModel* m, const mjData* d) {
  // The displacement after the step: s + h v+ while sticking; a sliding contact's spring
  // is left stretched just to its limit (s = -(f + C v+) / K), a rigid one unstretched.
  // Contacts that are gone (or do not push) are forgotten.
  const double h = m->opt.timestep;
  std::fill(dof_sliding_.begin(), dof_sliding_.end(), 0);
  MulA(false, af_.data());
  for (int k = 0; k < n_; k += group_size_[k]) {
    if (contact_[k] < 0) {
      const int dof = DryDof(d, k);
      if (dof >= 0) dof_sliding_[dof] = clamped_[k];
      continue;
    }
    const mjContact& con = d->contact[contact_[k]];
    Stick* st = FindStick(PairKey(con));
    if (!st) continue;
    st->sliding = clamped_[k];
    double s_new[3] = {0, 0, 0};
    for (int j = 0; j < std::min(group_size_[k], 2); ++j) {
      const int r = k + j;
      const double v = -h * (target_[r] - af_[r]);  // v+ = v + h (a + A f) = -h (target - A f)
      double s = disp_[r] + h * v;
      if (clamped_[k]) s = stiff_[r] > 0.0 ? -(f_[r] / stiff_[r] + h * v) : 0.0;
      for (int i = 0; i < 3; ++i) s_new[i] += s * con.frame[3 * (j + 1) + i];
    }
    for (int i = 0; i < 3; ++i) st->s[i] = s_new[i];
  }
  sticks_.erase(std::remove_if(sticks_.begin(), sticks_.end(), [](const Stick& s) { return !s.seen; }),
                sticks_.end());
}

bool FrictionPass::UseDampedMass(const mjModel* m, mjData* d, bool on) {
  // MuJoCo's Euler step integrates joint damping implicitly: its velocity update is
  // h (M + h B)^-1 (forces). The pass solves with that matrix, factored in MuJoCo's own
  // storage, and restores M's factor afterwards.
  const double h = m->opt.timestep;
  bool any = false;
  for (int i = 0; i < nv_; ++i) {
    if (m->dof_damping[i] <= 0.0) continue;
    d->qM[m->dof_Madr[i]] += (on ? h : -h) * m->dof_damping[i];
    any = true;
  }
  if (any) mj_factorM(m, d);
  return any;
}

void FrictionPass::WriteBack(const mjModel* m, mjData* d) {
  // New friction forces: qfrc_constraint = qfrc_nf + J' f, and
  // qacc = qacc_smooth + M^-1 qfrc_constraint.
  for (int c = 0; c < nv_; ++c) d->qfrc_constraint[c] = qfrc_nf_[c];
  for (int k = 0; k < n_; ++k) {
    d->efc_force[row_[k]] = f_[k];
    const int* cols = nz_col_.data() + static_cast<size_t>(k) * nv_;
    const double* vals = nz_val_.data() + static_cast<size_t>(k) * nv_;
    for (int t = 0; t < nz_count_[k]; ++t) d->qfrc_constraint[cols[t]] += vals[t] * f_[k];
  }
  mj_solveM(m, d, qfrc_.data(), d->qfrc_constraint, 1);
  for (int c = 0; c < nv_; ++c) d->qacc[c] = d->qacc_smooth[c] + qfrc_[c];
}

FrictionPassStats FrictionPass::Apply(const mjModel* m, mjData* d) {
  FrictionPassStats st;
  n_ = CollectRows(m, d);
  st.rows = n_;
  if (n_ == 0) {
    sticks_.clear();
    for (int c = 0; c < nv_; ++c) qfrc_nf_[c] = d->qfrc_constraint[c];
    WriteBack(m, d);
    return st;
  }
  const bool damped = UseDampedMass(m, d, true);
  BuildSystem(m, d);
  ContactSprings(m, d);
  StartFromLastState(d);
  // Solve with the free contacts sticking; release clamped ones that can stick and clamp
  // free ones outside their cone, until nothing changes.
  for (int round = 0; round < std::max(1, settings_.max_rounds); ++round) {
    SolveFree();
    ++st.rounds;
    const int released = UpdateClampedGroups();
    const int added = ClampOutsideLimits();
    if (released == 0 && added == 0) break;
  }
  for (int k = 0; k < n_; k += group_size_[k]) st.sliding += clamped_[k] ? 1 : 0;
  SaveState(m, d);
  if (damped) UseDampedMass(m, d, false);
  WriteBack(m, d);
  return st;
}

}  // namespace tactip
