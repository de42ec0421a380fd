#include "sim/friction_plane.h"

#include "sim/pressing_axis.h"

#include <mujoco/mujoco.h>

#include <algorithm>
#include <cmath>

namespace tactip {

namespace {
constexpr double kCancelled = 1e-12;   // relative size below which a combined Jacobian entry is a cancellation

}  // namespace

FrictionPlane::FrictionPlane(const mjModel* m)
    : axis_joint_(CompressionJoints(m)), scratch_(2 * static_cast<size_t>(m->nv)) {
  if (m->opt.cone != mjCONE_ELLIPTIC) return;
  for (int j : axis_joint_) active_ = active_ || j >= 0;
}

void FrictionPlane::CombineRows(const mjModel* m, mjData* d, int r1, int r2, int rn, const double w1[3],
                                const double w2[3]) const {
  // new r1 = w1 . (r1, r2, rn), new r2 = w2 . (r1, r2, rn), in efc_J, efc_JT and efc_vel;
  // friction rows have no position term, so their reference acceleration is -B vel.
  const int rows[3] = {r1, r2, rn};
  const auto combine = [&](double* v1, double* v2, double a, double b, double n) {
    const double x = w1[0] * a + w1[1] * b + w1[2] * n, y = w2[0] * a + w2[1] * b + w2[2] * n;
    *v1 = x;
    *v2 = y;
  };
  if (mj_isSparse(m)) {
    const int a1 = d->efc_J_rowadr[r1], a2 = d->efc_J_rowadr[r2], an = d->efc_J_rowadr[rn];
    const int nnz = d->efc_J_rownnz[r1];
    // New values first, then exact zeros where they cancel: motion along the axis (the
    // pin's own compression, a stage moving along it) has no component across it, and
    // keeping rounding residue there would make every row touch its pin's dof.
    double max1 = 0.0, max2 = 0.0;
    for (int t = 0; t < nnz; ++t) {
      combine(&scratch_[2 * t], &scratch_[2 * t + 1], d->efc_J[a1 + t], d->efc_J[a2 + t], d->efc_J[an + t]);
      max1 = std::max(max1, std::abs(scratch_[2 * t]));
      max2 = std::max(max2, std::abs(scratch_[2 * t + 1]));
    }
    for (int t = 0; t < nnz; ++t) {
      double* j1 = d->efc_J + a1 + t;
      double* j2 = d->efc_J + a2 + t;
      *j1 = std::abs(scratch_[2 * t]) > kCancelled * max1 ? scratch_[2 * t] : 0.0;
      *j2 = std::abs(scratch_[2 * t + 1]) > kCancelled * max2 ? scratch_[2 * t + 1] : 0.0;
      // The same two entries in the transposed Jacobian (its row = this column).
      const int c = d->efc_J_colind[a1 + t];
      const int* cols = d->efc_JT_colind + d->efc_JT_rowadr[c];
      const int len = d->efc_JT_rownnz[c];
      const int* p1 = std::lower_bound(cols, cols + len, r1);
      const int* p2 = std::lower_bound(cols, cols + len, r2);
      if (p1 != cols + len && *p1 == r1) d->efc_JT[d->efc_JT_rowadr[c] + (p1 - cols)] = *j1;
      if (p2 != cols + len && *p2 == r2) d->efc_JT[d->efc_JT_rowadr[c] + (p2 - cols)] = *j2;
    }
  } else {
    const int nv = m->nv, nefc = d->nefc;
    for (int c = 0; c < nv; ++c) {
      double *j1 = d->efc_J + r1 * nv + c, *j2 = d->efc_J + r2 * nv + c;
      combine(j1, j2, *j1, *j2, d->efc_J[rn * nv + c]);
      d->efc_JT[c * nefc + r1] = *j1;
      d->efc_JT[c * nefc + r2] = *j2;
    }
  }
  combine(d->efc_vel + r1, d->efc_vel + r2, d->efc_vel[r1], d->efc_vel[r2], d->efc_vel[rn]);
  for (int r : {r1, r2}) d->efc_aref[r] = -d->efc_KBIP[4 * r + 1] * d->efc_vel[r];
  (void)rows;
}

void FrictionPlane::Apply(const mjModel* m, mjData* d) const {
  if (!active_) return;
  const bool sparse = mj_isSparse(m);
  for (int i = 0; i < d->nefc; ++i) {
    if (d->efc_type[i] != mjCNSTR_CONTACT_ELLIPTIC) continue;
    mjContact& con = d->contact[d->efc_id[i]];
    const int dim = con.dim;
    const int b1 = m->geom_bodyid[con.geom1], b2 = m->geom_bodyid[con.geom2];
    const int jnt = axis_joint_[b1] >= 0 ? axis_joint_[b1] : axis_joint_[b2];
    const bool same_pattern = !sparse || d->efc_J_rownnz[i + 1] == d->efc_J_rownnz[i];
    double u1[3], u2[3];
    const double* n = con.frame;
    if (dim >= 3 && jnt >= 0 && same_pattern &&
        FrictionDirections(n, con.frame + 3, con.frame + 6, d->xaxis + 3 * jnt, u1, u2)) {
      // Each new row is its direction's components along (t1, t2, n) times the old rows.
      const double w1[3] = {mju_dot3(u1, con.frame + 3), mju_dot3(u1, con.frame + 6), mju_dot3(u1, n)};
      const double w2[3] = {mju_dot3(u2, con.frame + 3), mju_dot3(u2, con.frame + 6), mju_dot3(u2, n)};
      CombineRows(m, d, i + 1, i + 2, i, w1, w2);
      for (int k = 0; k < 3; ++k) {
        con.frame[3 + k] = u1[k];
        con.frame[6 + k] = u2[k];
      }
    }
    i += dim - 1;
  }
  // MuJoCo's own noslip pass works on the projected matrix, built from the old rows.
  if (m->opt.noslip_iterations > 0 || m->opt.solver == mjSOL_PGS) mj_projectConstraint(m, d);
}

}  // namespace tactip
