#include "sim/friction_pass.h"

#include <mujoco/mujoco.h>

#include <algorithm>
#include <cmath>

namespace tactip {

namespace {
constexpr double kGroupRegularization = 1e-9;  // a clamped group's own solve: relative diagonal weight
constexpr double kConeTolerance = 1e-9;   // relative excess over the cone before a contact is clamped

std::uint64_t PairKey(const mjContact& con) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(con.geom1)) << 32) |
         static_cast<std::uint32_t>(con.geom2);
}

double Dot3(const double* a, const double* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

}  // namespace

FrictionPass::FrictionPass(const mjModel* m, const FrictionPassSettings& settings)
    : settings_(settings), nv_(m->nv), delassus_(m, m->njmax) {
  const size_t rows = static_cast<size_t>(m->njmax);
  free_.resize(rows);
  for (auto* v : {&reg_, &spring_, &disp_, &stiff_, &capacity_, &target_, &f0_, &f_, &af_, &rhs_, &x_}) v->resize(rows);
  clamped_.resize(rows);
  for (auto* v : {&qfrc_, &qacc0_, &qfrc_nf_, &qLDiagInv_, &qLDiagSqrtInv_, &qM_diag_}) v->resize(nv_);
  qLD_.resize(m->nM);
  sticks_.reserve(static_cast<size_t>(m->nconmax) + 1);
  dof_sliding_.assign(nv_, 0);
}

void FrictionPass::BuildSystem(const mjModel* m, mjData* d) {
  // The stick velocity v = J qvel and the rigid-stick right-hand side -(v / h + J qacc_nf),
  // qacc_nf being the integrator's acceleration with every constraint force but friction
  // (qfrc_nf, kept for WriteBack: the main solver's friction forces are taken out). Then
  // the Delassus operator.
  const double h = m->opt.timestep;
  for (int c = 0; c < nv_; ++c) qfrc_nf_[c] = d->qfrc_constraint[c];
  for (int k = 0; k < n_; ++k) {
    const double f0 = d->efc_force[rows_.efc[k]];
    const int* cols = rows_.col.data() + static_cast<size_t>(k) * rows_.stride;
    const double* vals = rows_.val.data() + static_cast<size_t>(k) * rows_.stride;
    for (int t = 0; t < rows_.count[k]; ++t) qfrc_nf_[cols[t]] -= vals[t] * f0;
    f0_[k] = f0;
    f_[k] = 0.0;
    clamped_[k] = 0;
    capacity_[k] = rows_.mu[k] * rows_.limit[k];
  }
  for (int c = 0; c < nv_; ++c) qfrc_[c] = d->qfrc_smooth[c] + qfrc_nf_[c];
  mj_solveM(m, d, qacc0_.data(), qfrc_.data(), 1);
  for (int k = 0; k < n_; ++k) target_[k] = -rows_.Velocity(k, d->qvel) / h - rows_.Velocity(k, qacc0_.data());
  delassus_.Build(m, d, rows_);
}

FrictionPass::Stick* FrictionPass::FindStick(std::uint64_t key) {
  auto it = std::lower_bound(sticks_.begin(), sticks_.end(), key,
                             [](const Stick& a, std::uint64_t k) { return a.key < k; });
  return it != sticks_.end() && it->key == key ? &*it : nullptr;
}

FrictionPass::Stick& FrictionPass::StickOf(std::uint64_t key) {
  auto it = std::lower_bound(sticks_.begin(), sticks_.end(), key,
                             [](const Stick& a, std::uint64_t k) { return a.key < k; });
  if (it != sticks_.end() && it->key == key) return *it;
  Stick fresh;
  fresh.key = key;
  return *sticks_.insert(it, fresh);
}

void FrictionPass::ContactSprings(const mjModel* m, const mjData* d) {
  // Per contact row: displacement s since the contact stuck, along the row's direction;
  // the stiffness K = mu N / delta, damping C = K h, and the backward-Euler regularization
  // R = 1 / (h (K h + C)) with the spring's pull R K s. Rigid stick (delta = 0, torsion
  // and rolling rows, dry friction): R = 0 and the pull s / h^2 closes the gap in one step.
  const double h = m->opt.timestep;
  const double delta = settings_.presliding_m;
  for (auto& s : sticks_) s.seen = false;
  for (int k = 0; k < n_; k += rows_.group_size[k]) {
    for (int j = 0; j < rows_.group_size[k]; ++j) reg_[k + j] = spring_[k + j] = disp_[k + j] = stiff_[k + j] = 0.0;
    if (rows_.contact[k] < 0) continue;  // dry friction sticks rigidly
    Stick& st = StickOf(PairKey(d->contact[rows_.contact[k]]));
    st.seen = true;
    if (rows_.limit[k] > st.normal_N) {
      // Loading: the new share of the contact starts unstretched.
      const double keep = st.normal_N / rows_.limit[k];
      for (double& x : st.s) x *= keep;
    }
    st.normal_N = rows_.limit[k];
    for (int j = 0; j < rows_.group_size[k]; ++j) {
      const int r = k + j;
      const double s = Dot3(rows_.dir.data() + 3 * r, st.s);
      disp_[r] = s;
      if (delta <= 0.0 || j >= 2) {
        spring_[r] = s / (h * h);
        continue;
      }
      const double K = capacity_[r] / delta;
      const double C = K * h;  // damping time one step: dynamic forces stay in proportion to N too
      stiff_[r] = K;
      reg_[r] = 1.0 / (h * (K * h + C));
      spring_[r] = reg_[r] * K * s;
    }
  }
}

int FrictionPass::DryDof(const mjData* d, int k) const {
  const int i = rows_.efc[k];
  return d->efc_type[i] == mjCNSTR_FRICTION_DOF ? d->efc_id[i] : -1;
}

void FrictionPass::StartFromLastState(const mjData* d) {
  // Groups that were sliding at the end of the last step start clamped, their force on
  // the limit along last step's direction (or the main solver's when it had none);
  // UpdateClampedGroups releases them if they can stick now.
  for (int k = 0; k < n_; k += rows_.group_size[k]) {
    const int g = rows_.group_size[k];
    if (rows_.contact[k] < 0) {
      const int dof = DryDof(d, k);
      if (dof < 0 || !dof_sliding_[dof]) continue;
      f_[k] = f0_[k] >= 0.0 ? rows_.limit[k] : -rows_.limit[k];
      clamped_[k] = 1;
      continue;
    }
    const Stick* st = FindStick(PairKey(d->contact[rows_.contact[k]]));
    if (!st || !st->sliding) continue;
    double norm = 0.0;
    const bool had_force = Dot3(st->f, st->f) > 0.0;
    for (int j = 0; j < g; ++j) {
      f_[k + j] = had_force ? Dot3(rows_.dir.data() + 3 * (k + j), st->f) : f0_[k + j];
      norm += f_[k + j] * f_[k + j] / (rows_.mu[k + j] * rows_.mu[k + j]);
    }
    const double scale = norm > 0.0 ? rows_.limit[k] / std::sqrt(norm) : 0.0;
    for (int j = 0; j < g; ++j) {
      f_[k + j] *= scale;
      clamped_[k + j] = 1;
    }
  }
}

void FrictionPass::SolveFree() {
  // Free rows S, clamped rows C held at f_C: (A_SS + R_S) f_S = target_S - pull_S - A_SC f_C.
  int ns = 0;
  for (int k = 0; k < n_; ++k) {
    if (!clamped_[k]) free_[ns++] = k;
  }
  if (ns == 0) return;
  delassus_.Multiply(f_.data(), clamped_.data(), af_.data());
  for (int a = 0; a < ns; ++a) rhs_[a] = target_[free_[a]] - spring_[free_[a]] - af_[free_[a]];
  delassus_.SolveFree(ns, free_.data(), reg_.data(), capacity_.data(), rhs_.data(), x_.data());
  for (int a = 0; a < ns; ++a) f_[free_[a]] = x_[a];
}

int FrictionPass::UpdateClampedGroups() {
  // Each clamped group's force is put where it would stick given all the others (their
  // latest forces), then back onto its limit along that direction; a group whose sticking
  // force lies inside its limit is released.
  int released = 0;
  double M[25], x[5];
  delassus_.Track(f_.data());
  for (int k = 0; k < n_; k += rows_.group_size[k]) {
    if (!clamped_[k]) continue;
    const int g = rows_.group_size[k];
    for (int a = 0; a < g; ++a) {
      double r = target_[k + a] - spring_[k + a] - delassus_.RowTimesTracked(k + a);
      for (int c = 0; c < g; ++c) {
        M[a * g + c] = delassus_.At(k + a, k + c);
        r += M[a * g + c] * f_[k + c];
      }
      x[a] = r;
      M[a * g + a] += reg_[k + a] + kGroupRegularization * std::max(M[a * g + a], 1e-300);
    }
    mju_cholFactor(M, g, 1e-300);
    mju_cholSolve(x, M, x, g);
    double norm = 0.0;
    for (int a = 0; a < g; ++a) norm += x[a] * x[a] / (rows_.mu[k + a] * rows_.mu[k + a]);
    const bool inside = norm <= rows_.limit[k] * rows_.limit[k];
    const double scale = inside || norm <= 0.0 ? 1.0 : rows_.limit[k] / std::sqrt(norm);
    for (int a = 0; a < g; ++a) {
      delassus_.Change(k + a, x[a] * scale - f_[k + a]);
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
  for (int k = 0; k < n_; k += rows_.group_size[k]) {
    if (clamped_[k]) continue;
    const int g = rows_.group_size[k];
    double s = 0.0;
    for (int j = 0; j < g; ++j) s += f_[k + j] * f_[k + j] / (rows_.mu[k + j] * rows_.mu[k + j]);
    const double lim = rows_.limit[k];
    if (s <= lim * lim * (1.0 + kConeTolerance)) continue;
    const double scale = lim / std::sqrt(s);
    for (int j = 0; j < g; ++j) {
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
  delassus_.Multiply(f_.data(), nullptr, af_.data());
  for (int k = 0; k < n_; k += rows_.group_size[k]) {
    if (rows_.contact[k] < 0) {
      const int dof = DryDof(d, k);
      if (dof >= 0) dof_sliding_[dof] = clamped_[k];
      continue;
    }
    Stick* st = FindStick(PairKey(d->contact[rows_.contact[k]]));
    if (!st) continue;
    st->sliding = clamped_[k];
    double s_new[3] = {0, 0, 0}, f_new[3] = {0, 0, 0};
    for (int j = 0; j < std::min(rows_.group_size[k], 2); ++j) {
      const int r = k + j;
      const double v = -h * (target_[r] - af_[r]);  // v+ = v + h (a + A f) = -h (target - A f)
      double s = disp_[r] + h * v;
      if (clamped_[k]) s = stiff_[r] > 0.0 ? -(f_[r] / stiff_[r] + h * v) : 0.0;
      for (int i = 0; i < 3; ++i) {
        s_new[i] += s * rows_.dir[3 * r + i];
        f_new[i] += f_[r] * rows_.dir[3 * r + i];
      }
    }
    for (int i = 0; i < 3; ++i) st->s[i] = s_new[i], st->f[i] = f_new[i];
  }
  sticks_.erase(std::remove_if(sticks_.begin(), sticks_.end(), [](const Stick& s) { return !s.seen; }),
                sticks_.end());
}

bool FrictionPass::UseDampedMass(const mjModel* m, mjData* d, bool on) {
  // MuJoCo's Euler step integrates joint damping implicitly: its velocity update is
  // h (M + h B)^-1 (forces). The pass solves with that matrix, factored in MuJoCo's own
  // storage; M and its factor are kept aside and put back afterwards.
  const double h = m->opt.timestep;
  bool any = false;
  for (int i = 0; i < nv_ && !any; ++i) any = m->dof_damping[i] > 0.0;
  if (!any) return false;
  if (on) {
    std::copy(d->qLD, d->qLD + m->nM, qLD_.begin());
    std::copy(d->qLDiagInv, d->qLDiagInv + nv_, qLDiagInv_.begin());
    std::copy(d->qLDiagSqrtInv, d->qLDiagSqrtInv + nv_, qLDiagSqrtInv_.begin());
    for (int i = 0; i < nv_; ++i) {
      qM_diag_[i] = d->qM[m->dof_Madr[i]];
      d->qM[m->dof_Madr[i]] += h * m->dof_damping[i];
    }
    mj_factorM(m, d);
    return true;
  }
  for (int i = 0; i < nv_; ++i) d->qM[m->dof_Madr[i]] = qM_diag_[i];
  std::copy(qLD_.begin(), qLD_.end(), d->qLD);
  std::copy(qLDiagInv_.begin(), qLDiagInv_.end(), d->qLDiagInv);
  std::copy(qLDiagSqrtInv_.begin(), qLDiagSqrtInv_.end(), d->qLDiagSqrtInv);
  return true;
}

void FrictionPass::WriteBack(const mjModel* m, mjData* d) {
  // New friction forces: qfrc_constraint = qfrc_nf + J' f, and
  // qacc = qacc_smooth + M^-1 qfrc_constraint.
  for (int c = 0; c < nv_; ++c) d->qfrc_constraint[c] = qfrc_nf_[c];
  for (int k = 0; k < n_; ++k) {
    d->efc_force[rows_.efc[k]] = f_[k];
    const int* cols = rows_.col.data() + static_cast<size_t>(k) * rows_.stride;
    const double* vals = rows_.val.data() + static_cast<size_t>(k) * rows_.stride;
    for (int t = 0; t < rows_.count[k]; ++t) d->qfrc_constraint[cols[t]] += vals[t] * f_[k];
  }
  mj_solveM(m, d, qfrc_.data(), d->qfrc_constraint, 1);
  for (int c = 0; c < nv_; ++c) d->qacc[c] = d->qacc_smooth[c] + qfrc_[c];
}

FrictionPassStats FrictionPass::Apply(const mjModel* m, mjData* d) {
  FrictionPassStats st;
  ReadFrictionRows(m, d, rows_);
  n_ = rows_.n;
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
  for (int k = 0; k < n_; k += rows_.group_size[k]) st.sliding += clamped_[k] ? 1 : 0;
  SaveState(m, d);
  if (damped) UseDampedMass(m, d, false);
  WriteBack(m, d);
  return st;
}

}  // namespace tactip
