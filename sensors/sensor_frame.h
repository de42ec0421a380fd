#pragma once
// The sensor frame: x along the dome axis (outwards, towards the stimulus), z up, origin at
// the dome centre. Conversions from the world frame given the sensor body's pose.

#include <array>

namespace tactip {

/// A sensor body's world pose: origin (m) and rotation (row-major, columns = sensor axes).
struct SensorPose {
  std::array<double, 3> origin{};
  std::array<double, 9> rot{};

  /// A world point in the sensor frame: R^T (p - origin).
  std::array<double, 3> Point(const std::array<double, 3>& p) const {
    const double d[3] = {p[0] - origin[0], p[1] - origin[1], p[2] - origin[2]};
    return {rot[0] * d[0] + rot[3] * d[1] + rot[6] * d[2], rot[1] * d[0] + rot[4] * d[1] + rot[7] * d[2],
            rot[2] * d[0] + rot[5] * d[1] + rot[8] * d[2]};
  }
  /// A world vector (not a point) in the sensor frame, as the image of the point origin + v
  /// (the rounding every dataset so far was written with).
  std::array<double, 3> Vector(const std::array<double, 3>& v) const {
    return Point({origin[0] + v[0], origin[1] + v[1], origin[2] + v[2]});
  }
};

}  // namespace tactip
