#pragma once
// Contact friction in the plane perpendicular to each pin's pressing axis.
//
// A pin's normal dof stands for the skin being pressed in; it moves along a fixed axis
// (its "compression" joint, user value 1 in the MJCF: see models/skin.h). On a sloped
// surface a contact's tangent plane is tilted against that axis, so with MuJoCo's own rows
// every press or release along the axis would be partly tangential: friction would fight
// the skin's compression, a sticking contact could not compress, and retracting the sensor
// would look like slip. After MuJoCo builds the constraints (mj_step1) and before it solves
// them, this turns each such contact's friction directions into the plane perpendicular to
// the pressing axis: the first tangent is put perpendicular to the axis (in the contact's
// tangent plane) and the second is the remaining tangent with its component along the axis
// taken out. Relative motion along the axis is compression, not slip; friction resists
// relative motion across it. Efc rows (J, J', velocity, reference acceleration) and the
// contact frame are updated together, so the solver, the friction pass and the contact
// read-out agree. Contacts whose normal already lies along the axis are left as they are,
// and so are sideways touches (normal more than 60 degrees from the axis: pressing along
// the axis does not load them, so motion along it is real sliding).

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

/// The user value that flags a compression joint.
inline constexpr double kCompressionJointUser = 1.0;

}  // namespace tactip
