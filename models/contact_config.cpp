#include "models/contact_config.h"

#include <fmt/format.h>

namespace tactip {

void ContactConfig::ValidateRules() const {
  if (impedance_min > impedance) {
    FailRule("contact.impedance_min", impedance_min, fmt::format("must be <= contact.impedance = {}", impedance));
  }
  if (slip_memory_um > 0.0 && !(weakening_speed_mm_s > 0.0)) {
    FailRule("contact.slip_memory_um", slip_memory_um,
             "needs contact.weakening_speed_mm_s > 0 (it delays the velocity weakening)");
  }
  if (breakaway_ratio < kinetic_ratio) {
    FailRule("contact.breakaway_ratio", breakaway_ratio,
             fmt::format("must be >= contact.kinetic_ratio = {} (friction drops to it at breakaway, then on to kinetic)",
                         kinetic_ratio));
  }
}

}  // namespace tactip
