#include "models/scene_size.h"

#include <algorithm>

namespace tactip {

SceneSize EstimateRailScene(const RailSceneSpec& spec) {
  const PinLattice lattice = PinLattice::Build(spec.skin);
  const int n_lattice = static_cast<int>(lattice.size());
  SceneSize s;
  for (const SensorMountConfig& mount : spec.sensors) {
    std::vector<bool> collidable =
        RailCollidablePins(spec.skin, lattice, spec.rail, spec.max_depth_m, mount.offset_y_mm * 1e-3);
    if (spec.options.all_pins_collide) collidable.assign(lattice.size(), true);
    const int n_collidable = static_cast<int>(std::count(collidable.begin(), collidable.end(), true));
    s.n_pins += n_lattice;
    s.n_collidable += n_collidable;
    // The skin's DOFs as BuildSkin makes them: shell - two shell shear DOFs and a normal DOF
    // per pin; membrane - two shear DOFs per pin, a normal DOF per collidable pin; none -
    // three per pin.
    const std::string& coupling = spec.skin.coupling;
    if (coupling == "shell") {
      s.nv += 2 + n_lattice;
    } else if (coupling == "membrane") {
      s.nv += 2 * n_lattice + n_collidable;
    } else {
      s.nv += 3 * n_lattice;
    }
  }
  // The rig adds the arm's two stages and the object's joint.
  s.nv += 2 + (spec.options.object_free_joint ? 6 : 1);
  s.njmax = SceneContactBudget(spec.sim, s.n_collidable).njmax;
  const double rows = static_cast<double>(s.njmax) + s.nv;
  s.stack_bytes = 5.0 * rows * rows * 8.0;
  return s;
}

}  // namespace tactip
