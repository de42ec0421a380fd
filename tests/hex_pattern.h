#pragma once
// A flat hexagonal pin pattern in image pixels, for the tests of the pin noise and its report.

#include <cmath>
#include <cstdlib>
#include <vector>

namespace tactip::testing {

/// `rings` hexagonal rings about (320, 240), `pitch_px` apart: 1 + 3 rings (rings + 1) pins
/// (127 for 6 rings), row-major (u, v).
inline std::vector<float> HexPattern(int rings, double pitch_px) {
  std::vector<float> px;
  for (int q = -rings; q <= rings; ++q) {
    for (int r = -rings; r <= rings; ++r) {
      if (std::abs(q + r) > rings) continue;
      px.push_back(static_cast<float>(320.0 + pitch_px * (q + 0.5 * r)));
      px.push_back(static_cast<float>(240.0 + pitch_px * (std::sqrt(3.0) / 2.0) * r));
    }
  }
  return px;
}

}  // namespace tactip::testing
