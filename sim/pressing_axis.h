#pragma once
// The friction directions of a contact on a pin: across the pin's pressing axis.
//
// A pin's normal dof stands for the skin being pressed in; it moves along a fixed axis
// (its "compression" joint, user value 1 in the MJCF: see models/skin.h). On a sloped
// surface a contact's tangent plane is tilted against that axis, so friction along the
// contact's own tangents would fight the skin's compression: a sticking contact could not
// compress, and retracting the sensor would look like slip. Relative motion along the axis
// is compression, not slip; friction resists relative motion across it. The first friction
// direction is put perpendicular to the axis in the contact's tangent plane, the second is
// the remaining tangent with its component along the axis taken out (the two stay
// orthonormal). Contacts whose normal already lies along the axis keep their tangents, and
// so do sideways touches (normal more than 60 degrees from the axis: pressing along the
// axis does not load them, so motion along it is real sliding).

#include <vector>

struct mjModel_;

namespace tactip {

/// The user value that flags a compression joint.
inline constexpr double kCompressionJointUser = 1.0;

/// Per body: its compression joint (a slide joint with user value 1), or -1.
std::vector<int> CompressionJoints(const mjModel_* m);

/// Friction directions of a contact with unit normal n and tangents t1, t2 on a body
/// pressed along the unit axis a (nullptr: no pressing axis). Writes u1, u2 and returns
/// true when they were turned across the axis, false when they are t1, t2.
bool FrictionDirections(const double n[3], const double t1[3], const double t2[3], const double* a, double u1[3],
                        double u2[3]);

}  // namespace tactip
