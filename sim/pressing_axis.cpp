#include "sim/pressing_axis.h"

#include <mujoco/mujoco.h>

#include <cmath>

namespace tactip {

namespace {
constexpr double kAlignedSine = 1e-9;  // |n x axis| below this: the normal lies along the axis already
constexpr double kMaxTiltCos = 0.5;    // contacts tilted more than 60 deg from the axis are sideways touches

void Cross(const double* a, const double* b, double* out) {
  out[0] = a[1] * b[2] - a[2] * b[1];
  out[1] = a[2] * b[0] - a[0] * b[2];
  out[2] = a[0] * b[1] - a[1] * b[0];
}
}  // namespace

std::vector<int> CompressionJoints(const mjModel* m) {
  std::vector<int> joint(m->nbody, -1);
  if (m->nuser_jnt < 1) return joint;
  for (int j = 0; j < m->njnt; ++j) {
    if (m->jnt_user[j * m->nuser_jnt] != kCompressionJointUser || m->jnt_type[j] != mjJNT_SLIDE) continue;
    if (joint[m->jnt_bodyid[j]] < 0) joint[m->jnt_bodyid[j]] = j;
  }
  return joint;
}

bool FrictionDirections(const double n[3], const double t1[3], const double t2[3], const double* a, double u1[3],
                        double u2[3]) {
  const auto keep = [&] {
    for (int k = 0; k < 3; ++k) u1[k] = t1[k], u2[k] = t2[k];
    return false;
  };
  if (!a) return keep();
  Cross(n, a, u1);
  const double sine = std::sqrt(mju_dot3(u1, u1));
  if (sine < kAlignedSine || std::abs(mju_dot3(n, a)) < kMaxTiltCos) return keep();
  for (int k = 0; k < 3; ++k) u1[k] /= sine;
  double w[3];
  Cross(n, u1, w);
  const double p = mju_dot3(w, a), q = std::sqrt(1.0 - p * p);
  for (int k = 0; k < 3; ++k) u2[k] = (w[k] - p * a[k]) / q;
  return true;
}

}  // namespace tactip
