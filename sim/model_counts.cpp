#include "sim/model_counts.h"

#include <mujoco/mujoco.h>

#include "sim/simulation.h"

namespace tactip {

ModelCounts CountModel(const CompiledModel& model) {
  const mjModel* m = model.raw();
  ModelCounts c;
  c.nv = m->nv;
  c.nbody = m->nbody;
  c.ngeom = m->ngeom;
  for (int g = 0; g < m->ngeom; ++g) c.ngeom_collidable += (m->geom_contype[g] || m->geom_conaffinity[g]) ? 1 : 0;
  c.nsite = m->nsite;
  c.ncam = m->ncam;
  c.nlight = m->nlight;
  c.nconmax = m->nconmax;
  c.njmax = m->njmax;
  c.nstack = m->nstack;
  return c;
}

}  // namespace tactip
