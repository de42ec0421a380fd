#include "sim/base/number_text.h"

#include <cmath>

#include <fmt/format.h>

namespace tactip {

std::string NumberCell(double v, const char* spec, const char* missing) {
  return std::isnan(v) ? std::string(missing) : fmt::format(fmt::runtime(spec), v);
}

}  // namespace tactip
