#pragma once
// The value type everything downstream of the camera speaks: one camera frame of
// pin positions, from the simulator or from real TacTip hardware.

#include <vector>

#include <Eigen/Core>

namespace tactip {

/// One camera frame of N tracked pins.
struct PinFrame {
  double time_s = 0.0;                         ///< frame time
  Eigen::Matrix<float, Eigen::Dynamic, 2> pos_px;  ///< N x 2 pin positions (u right, v down), px
  std::vector<unsigned char> valid;            ///< N, 1 = detected in this frame
  /// Optional N x 2 external marker positions (empty when there is no external camera).
  Eigen::Matrix<float, Eigen::Dynamic, 2> external_px;

  /// Number of pins N.
  int size() const { return static_cast<int>(pos_px.rows()); }
};

}  // namespace tactip
