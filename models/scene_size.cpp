#include "models/scene_size.h"

#include <algorithm>

namespace tactip {

SceneSize EstimateRailScene(const RailSceneSpec& spec) {
  const PinLattice lattice = PinLattice::Build(spec.skin);
  std::vector<bool> collidable = RailCollidablePins(spec.skin, lattice, spec.rail, spec.max_depth_m);
  if (spec.options.all_pins_collide) collidable.assign(lattice.size(), true);
  SceneSize s;
  s.n_pins = static_cast<int>(lattice.size());
  s.n_collidable = static_cast<int>(std::count(collidable.begin(), collidable.end(), true));
  // The skin's DOFs as BuildSkin makes them: shell - two shell shear DOFs and a normal DOF
  // per pin; membrane - two shear DOFs per pin, a normal DOF per collidable pin; none -
  // three per pin. The rig adds the arm's two stages and the object's joint.
  const std::string& coupling = spec.skin.coupling;
  if (coupling == "shell") {
    s.nv = 2 + s.n_pins;
  } else if (coupling == "membrane") {
    s.nv = 2 * s.n_pins + s.n_collidable;
  } else {
    s.nv = 3 * s.n_pins;
  }
  s.nv += 2 + (spec.options.object_free_joint ? 6 : 1);
  s.njmax = SceneContactBudget(spec.sim, s.n_collidable).njmax;
  const double rows = static_cast<double>(s.njmax) + s.nv;
  s.stack_bytes = 5.0 * rows * rows * 8.0;
  return s;
}

}  // namespace tactip
