#include "sim/friction_rows.h"

#include <mujoco/mujoco.h>

namespace tactip {

double FrictionRows::Velocity(int r, const double* qvel) const {
  const int* c = col.data() + static_cast<size_t>(r) * stride;
  const double* v = val.data() + static_cast<size_t>(r) * stride;
  double acc = 0.0;
  for (int t = 0; t < count[r]; ++t) acc += v[t] * qvel[c[t]];
  return acc;
}

namespace {

void CopyRow(const mjModel* m, const mjData* d, int i, int r, FrictionRows& rows) {
  const int nv = m->nv;
  int* cols = rows.col.data() + static_cast<size_t>(r) * nv;
  double* vals = rows.val.data() + static_cast<size_t>(r) * nv;
  int nz = 0;
  if (mj_isSparse(m)) {
    const int adr = d->efc_J_rowadr[i];
    for (int t = 0; t < d->efc_J_rownnz[i]; ++t) {
      if (d->efc_J[adr + t] == 0.0) continue;
      cols[nz] = d->efc_J_colind[adr + t];
      vals[nz++] = d->efc_J[adr + t];
    }
  } else {
    for (int c = 0; c < nv; ++c) {
      const double v = d->efc_J[static_cast<size_t>(i) * nv + c];
      if (v == 0.0) continue;
      cols[nz] = c;
      vals[nz++] = v;
    }
  }
  rows.count[r] = nz;
}

}  // namespace

void ReadFrictionRows(const mjModel* m, mjData* d, FrictionRows& rows) {
  const size_t room = static_cast<size_t>(m->njmax);
  if (rows.efc.size() < room) {
    for (auto* v : {&rows.efc, &rows.contact, &rows.group_size, &rows.count}) v->resize(room);
    for (auto* v : {&rows.limit, &rows.mu}) v->resize(room);
    rows.dir.resize(3 * room);
    rows.col.resize(room * m->nv);
    rows.val.resize(room * m->nv);
  }
  rows.stride = m->nv;
  int n = 0;
  for (int i = 0; i < d->nefc; ++i) {
    const int type = d->efc_type[i];
    if (type == mjCNSTR_FRICTION_DOF || type == mjCNSTR_FRICTION_TENDON) {
      rows.efc[n] = i, rows.contact[n] = -1, rows.group_size[n] = 1;
      rows.limit[n] = d->efc_frictionloss[i], rows.mu[n] = 1.0;
      for (int k = 0; k < 3; ++k) rows.dir[3 * n + k] = 0.0;
      CopyRow(m, d, i, n++, rows);
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
      rows.efc[n] = i + j, rows.contact[n] = d->efc_id[i], rows.group_size[n] = con.dim - 1;
      rows.limit[n] = fn, rows.mu[n] = con.friction[j - 1];
      for (int k = 0; k < 3; ++k) rows.dir[3 * n + k] = j < 3 ? con.frame[3 * j + k] : 0.0;
      CopyRow(m, d, i + j, n++, rows);
    }
    i += con.dim - 1;
  }
  rows.n = n;
}

}  // namespace tactip
