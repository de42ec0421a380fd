#include "sensors/state_limits.h"

#include <algorithm>
#include <numeric>

#include <fmt/format.h>

namespace tactip {

namespace {
constexpr double kContactMarginM = 1e-3;  // as the culling of pins that cannot touch
}  // namespace

StateLimits StateLimits::For(const SkinConfig& skin, double deepest_press_mm, double load_N, int n_collidable,
                             double extra_press_m) {
  const PinLattice lattice = PinLattice::Build(skin);
  const SkinMechanics mech = SkinMechanics::From(skin, lattice);
  const double omega = mech.StiffestOmega();
  const double k_pin = omega * omega * mech.pin_mass_kg;  // k_normal dome_gain + 12 k_bend
  const double press_m = std::max(0.0, deepest_press_mm) * 1e-3 + extra_press_m + kContactMarginM;
  StateLimits l;
  l.max_marker_shift_m = skin.OuterRadiusMm() * 1e-3;
  l.max_pin_force_N = kAbsurdFactor * (k_pin * press_m + load_N);
  l.max_total_force_N = kAbsurdFactor * (n_collidable * k_pin * press_m + load_N);
  return l;
}

std::string ImplausibleState(const StateLimits& limits, const std::vector<double>& marker_shift_m,
                             const std::vector<double>& normal_N) {
  // !(x <= limit) also catches NaN.
  for (size_t i = 0; i < marker_shift_m.size(); ++i) {
    if (!(marker_shift_m[i] <= limits.max_marker_shift_m)) {
      return fmt::format("pin {}'s marker is {:.3g} mm from where it rests, beyond the dome's {:.3g} mm radius", i,
                         marker_shift_m[i] * 1e3, limits.max_marker_shift_m * 1e3);
    }
  }
  const double f = StateLimits::kAbsurdFactor;
  for (size_t i = 0; i < normal_N.size(); ++i) {
    if (!(normal_N[i] <= limits.max_pin_force_N)) {
      return fmt::format("pin {} carries {:.3g} N, more than {} times the {:.3g} N that the deepest press and the "
                         "object's weight allow",
                         i, normal_N[i], f, limits.max_pin_force_N / f);
    }
  }
  const double total = std::accumulate(normal_N.begin(), normal_N.end(), 0.0);
  if (!(total <= limits.max_total_force_N)) {
    return fmt::format("the pins carry {:.3g} N in total, more than {} times the {:.3g} N that the deepest press on "
                       "every pin that can touch and the object's weight allow",
                       total, f, limits.max_total_force_N / f);
  }
  return {};
}

}  // namespace tactip
