#include "sim/friction_reference.h"

#include <mujoco/mujoco.h>

#include <algorithm>
#include <cmath>

namespace tactip {

void FadeFrictionReference(mjData* d, double sliding_speed_m_s) {
  for (int i = 0; i < d->nefc; ++i) {
    if (d->efc_type[i] != mjCNSTR_CONTACT_ELLIPTIC) continue;
    const int dim = d->contact[d->efc_id[i]].dim;
    double v2 = 0.0;
    for (int j = 1; j < std::min(dim, 3); ++j) v2 += d->efc_vel[i + j] * d->efc_vel[i + j];
    if (v2 > sliding_speed_m_s * sliding_speed_m_s) {
      const double scale = std::max(0.0, 2.0 - std::sqrt(v2) / sliding_speed_m_s);
      for (int j = 1; j < dim; ++j) d->efc_aref[i + j] *= scale;
    }
    i += dim - 1;
  }
}

}  // namespace tactip
