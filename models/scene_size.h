#pragma once
// What a rail scene asks of MuJoCo, estimated from its spec without building the MJCF: the
// pin count, the degrees of freedom, the constraint rows, and the solver stack MuJoCo
// reserves per run. A skin with thousands of pins makes that stack grow past what a machine
// can allocate (MuJoCo then fails to create its data after a long compile), so configs are
// checked against it before anything is built.

#include "models/rail_rig.h"

namespace tactip {

/// Most solver stack one run may reserve, bytes (the default scenes reserve 6-12 MB).
inline constexpr double kMaxSolverStackBytes = 1024.0 * 1024.0 * 1024.0;

/// The size of a rail scene.
struct SceneSize {
  int n_pins = 0;        ///< pins of all sensors
  int n_collidable = 0;  ///< pins that can touch the stimulus (they carry a contact geom), of all sensors
  int nv = 0;            ///< degrees of freedom
  int njmax = 0;         ///< constraint-row budget
  /// The stack MuJoCo reserves per mjData when the model does not set one:
  /// 5 (njmax + nv)^2 numbers of 8 bytes (its compiler's heuristic, dominant term).
  double stack_bytes = 0.0;
  bool Fits() const { return stack_bytes <= kMaxSolverStackBytes; }
};

/// The size of the scene BuildRailScene(spec) builds.
SceneSize EstimateRailScene(const RailSceneSpec& spec);

}  // namespace tactip
