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

// Solves M x = b in place for an n x n row-major matrix (LU with partial pivoting);
// M is overwritten by its factors and b by x.
void SolveLu(double* M, double* b, int n, int* piv) {
  for (int c = 0; c < n; ++c) {
    int p = c;
    for (int r = c + 1; r < n; ++r) {
      if (std::abs(M[r * n + c]) > std::abs(M[p * n + c])) p = r;
    }
    piv[c] = p;
    if (p != c) {
      for (int k = 0; k < n; ++k) std::swap(M[c * n + k], M[p * n + k]);
      std::swap(b[c], b[p]);
    }
    const double d = M[c * n + c];
    if (d == 0.0) continue;
    for (int r = c + 1; r < n; ++r) {
      const double l = M[r * n + c] / d;
      if (l == 0.0) continue;
      M[r * n + c] = l;
      for (int k = c + 1; k < n; ++k) M[r * n + k] -= l * M[c * n + k];
      b[r] -= l * b[c];
    }
  }
  for (int r = n - 1; r >= 0; --r) {
    double s = b[r];
    for (int k = r + 1; k < n; ++k) s -= M[r * n + k] * b[k];
    b[r] = M[r * n + r] != 0.0 ? s / M[r * n + r] : 0.0;
  }
}
}  // namespace

FrictionPass::FrictionPass(const mjModel* m, const FrictionPassSettings& settings)
    : settings_(settings), nv_(m->nv) {
  const size_t rows = static_cast<size_t>(m->njmax);
  for (auto* v : {&row_, &contact_, &group_size_, &nz_count_, &free_, &piv_}) v->resize(rows);
  for (auto* v : {&limit_, &mu_, &reg_, &spring_, &disp_, &stiff_, &target_, &f0_, &f_, &rhs_, &x_}) {
    v->resize(rows);
  }
  clamped_.resize(rows);
  for (auto* v : {&Js_, &X_}) v->resize(rows * nv_);
  nz_col_.resize(rows * nv_);
  A_.resize(rows * rows);
  L_.resize(rows * rows);
  qfrc_.resize(nv_);
  qacc0_.resize(nv_);
  qfrc_nf_.resize(nv_);
  sticks_.reserve(static_cast<size_t>(m->nconmax) + 1);
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
  // Friction-row Jacobian J (dense rows, with their non-zero columns), X = (M + h B)^-1 J',
  // A = J X' (symmetric), the stick velocity v = J qvel, and the rigid-stick right-hand
  // side -(v / h + J qacc_nf), qacc_nf being the integrator's acceleration with every
  // constraint force but friction (qfrc_nf, kept for WriteBack).
  const bool sparse = mj_isSparse(m);
  const double h = m->opt.timestep;
  const size_t nn = static_cast<size_t>(n_) * nv_;
  std::fill(Js_.begin(), Js_.begin() + nn, 0.0);
  for (int c = 0; c < nv_; ++c) qfrc_nf_[c] = d->qfrc_constraint[c];
  for (int k = 0; k < n_; ++k) {
    double* js = Js_.data() + static_cast<size_t>(k) * nv_;
    const int i = row_[k];
    const double f0 = d->efc_force[i];
    const auto take = [&](int c, double jv) {
      qfrc_nf_[c] -= jv * f0;  // take the main solver's friction out
      js[c] = jv;
    };
    if (sparse) {
      const int adr = d->efc_J_rowadr[i];
      for (int t = 0; t < d->efc_J_rownnz[i]; ++t) take(d->efc_J_colind[adr + t], d->efc_J[adr + t]);
    } else {
      for (int c = 0; c < nv_; ++c) take(c, d->efc_J[static_cast<size_t>(i) * nv_ + c]);
    }
    int* cols = nz_col_.data() + static_cast<size_t>(k) * nv_;
    int nz = 0;
    for (int c = 0; c < nv_; ++c) {
      if (js[c] != 0.0) cols[nz++] = c;
    }
    nz_count_[k] = nz;
    f0_[k] = f_[k] = f0;
    clamped_[k] = 0;
  }
  mj_solveM(m, d, X_.data(), Js_.data(), n_);
  for (int c = 0; c < nv_; ++c) qfrc_[c] = d->qfrc_smooth[c] + qfrc_nf_[c];
  mj_solveM(m, d, qacc0_.data(), qfrc_.data(), 1);
  for (int k = 0; k < n_; ++k) {
    const double* js = Js_.data() + static_cast<size_t>(k) * nv_;
    const int* cols = nz_col_.data() + static_cast<size_t>(k) * nv_;
    double v = 0.0, a = 0.0;
    for (int t = 0; t < nz_count_[k]; ++t) {
      v += js[cols[t]] * d->qvel[cols[t]];
      a += js[cols[t]] * qacc0_[cols[t]];
    }
    for (int l = 0; l <= k; ++l) {
      const double* xl = X_.data() + static_cast<size_t>(l) * nv_;
      double s = 0.0;
      for (int t = 0; t < nz_count_[k]; ++t) s += js[cols[t]] * xl[cols[t]];
      A_[static_cast<size_t>(k) * n_ + l] = A_[static_cast<size_t>(l) * n_ + k] = s;
    }
    target_[k] = -v / h - a;
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
    if (c < 0) continue;
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

void FrictionPass::StartFromLastState(const mjData* d) {
  // Groups that were sliding at the end of the last step start clamped, their force on
  // the limit along the main solver's direction; UpdateClampedGroups releases them if
  // they can stick now.
  for (int k = 0; k < n_; k += group_size_[k]) {
    if (contact_[k] < 0) continue;
    const Stick* st = FindStick(PairKey(d->contact[contact_[k]]));
    if (!st || !st->sliding) continue;
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
  // Rigid rows that share bodies make A_SS singular (internal forces between them move
  // nothing); among their solutions the one taken loads each contact in proportion to its
  // capacity (minimum sum f^2 / (mu N)^2), through a tiny weight on the diagonal.
  int ns = 0;
  double max_diag = 0.0, max_cap = kMinCapacity;
  for (int k = 0; k < n_; ++k) {
    if (clamped_[k]) continue;
    free_[ns++] = k;
    max_diag = std::max(max_diag, A_[static_cast<size_t>(k) * n_ + k]);
    max_cap = std::max(max_cap, mu_[k] * limit_[k]);
  }
  if (ns == 0) return;
  const double eps = kRegularization * std::max(max_diag, 1e-300);
  for (int a = 0; a < ns; ++a) {
    const int k = free_[a];
    const double* ak = A_.data() + static_cast<size_t>(k) * n_;
    double r = target_[k] - spring_[k];
    for (int l = 0; l < n_; ++l) {
      if (clamped_[l]) r -= ak[l] * f_[l];
    }
    x_[a] = r;
    for (int b = 0; b < ns; ++b) L_[static_cast<size_t>(a) * ns + b] = ak[free_[b]];
    const double cap = std::max(mu_[k] * limit_[k], kMinCapacity) / max_cap;
    L_[static_cast<size_t>(a) * ns + a] += reg_[k] + (reg_[k] > 0.0 ? 0.0 : eps / (cap * cap));
  }
  SolveLu(L_.data(), x_.data(), ns, piv_.data());
  for (int a = 0; a < ns; ++a) f_[free_[a]] = x_[a];
}

int FrictionPass::UpdateClampedGroups() {
  // Each clamped group's force is put where it would stick given all the others, then
  // back onto its limit along that direction; a group whose sticking force lies inside its
  // limit is released.
  int released = 0;
  double M[25], x[5];
  int piv[5];
  for (int k = 0; k < n_; k += group_size_[k]) {
    if (!clamped_[k]) continue;
    const int g = group_size_[k];
    for (int a = 0; a < g; ++a) {
      const double* ar = A_.data() + static_cast<size_t>(k + a) * n_;
      double r = target_[k + a] - spring_[k + a];
      for (int l = 0; l < n_; ++l) {
        if (l < k || l >= k + g) r -= ar[l] * f_[l];
      }
      x[a] = r;
      for (int c = 0; c < g; ++c) M[a * g + c] = ar[k + c];
      M[a * g + a] += reg_[k + a] + kRegularization * std::max(ar[k + a], 1e-300);
    }
    SolveLu(M, x, g, piv);
    double norm = 0.0;
    for (int a = 0; a < g; ++a) norm += x[a] * x[a] / (mu_[k + a] * mu_[k + a]);
    const bool inside = norm <= limit_[k] * limit_[k];
    const double scale = inside || norm <= 0.0 ? 1.0 : limit_[k] / std::sqrt(norm);
    for (int a = 0; a < g; ++a) {
      f_[k + a] = x[a] * scale;
      if (inside) clamped_[k + a] = 0;
    }
    released += inside ? 1 : 0;
  }
  return released;
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
  for (int k = 0; k < n_; k += group_size_[k]) {
    if (contact_[k] < 0) continue;
    const mjContact& con = d->contact[contact_[k]];
    Stick* st = FindStick(PairKey(con));
    if (!st) continue;
    st->sliding = clamped_[k];
    double s_new[3] = {0, 0, 0};
    for (int j = 0; j < std::min(group_size_[k], 2); ++j) {
      const int r = k + j;
      const double* ar = A_.data() + static_cast<size_t>(r) * n_;
      double af = 0.0;
      for (int l = 0; l < n_; ++l) af += ar[l] * f_[l];
      const double v = -h * (target_[r] - af);  // v+ = v + h (a + A f) = -h (target - A f)
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
    const double* js = Js_.data() + static_cast<size_t>(k) * nv_;
    const int* cols = nz_col_.data() + static_cast<size_t>(k) * nv_;
    for (int t = 0; t < nz_count_[k]; ++t) d->qfrc_constraint[cols[t]] += js[cols[t]] * f_[k];
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
