#pragma once
// Contact friction in the plane perpendicular to each pin's pressing axis.
//
// After MuJoCo builds the constraints (mj_step1) and before it solves them, this turns
// each contact's friction rows into the directions across the pin's pressing axis (see
// sim/pressing_axis.h). Efc rows (J, J', velocity, reference acceleration) and the contact
// frame are updated together, so the solver, the friction pass (or MuJoCo's noslip) and the
// contact read-out agree.

#include <vector>

struct mjModel_;
struct mjData_;

namespace tactip {

/// Turns contact friction rows into the planes perpendicular to the pressing axes.
class FrictionPlane {
 public:
  explicit FrictionPlane(const mjModel_* m);
  /// True when some body has a compression joint and the cones are elliptic.
  bool active() const { return active_; }
  /// Call after mj_step1 (or mj_forward's position and velocity stages), before the
  /// constraint solve.
  void Apply(const mjModel_* m, mjData_* d) const;

 private:
  void CombineRows(const mjModel_* m, mjData_* d, int r1, int r2, int rn, const double w1[3],
                   const double w2[3]) const;
  std::vector<int> axis_joint_;  // per body: its compression joint, or -1
  mutable std::vector<double> scratch_;  // 2 x nv: combined row values
  bool active_ = false;
};

}  // namespace tactip
