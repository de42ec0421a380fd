#pragma once
// What a compiled model contains, counted: to compare scenes built with and without parts.

namespace tactip {

class CompiledModel;

/// Element counts of a compiled model.
struct ModelCounts {
  int nv = 0;                ///< degrees of freedom
  int nbody = 0;             ///< bodies, the world included
  int ngeom = 0;             ///< geoms
  int ngeom_collidable = 0;  ///< geoms with a contype or conaffinity bit (the rest are visual only)
  int nsite = 0;             ///< sites
  int ncam = 0;              ///< cameras
  int nlight = 0;            ///< lights
  int nconmax = 0;           ///< contact budget (sizes mjData)
  int njmax = 0;             ///< constraint-row budget (sizes mjData)
  long long nstack = 0;      ///< solver stack each mjData reserves, in numbers (8 bytes each)
};

ModelCounts CountModel(const CompiledModel& model);

}  // namespace tactip
