#pragma once
// The quiet NaN every figure, table and attribute uses for "not measured" or "did not happen".

#include <limits>

namespace tactip {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace tactip
