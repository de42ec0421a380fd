#include "models/ridge_rocking.h"

#include <numbers>
#include <stdexcept>

namespace tactip {

namespace {
constexpr double kGelPoisson = 0.5;  // the silicone gel is nearly incompressible
}  // namespace

double RockingGelStiffness(const std::string& model, double E_gel, double h_gel, double b, double w) {
  if (model == "winkler") return (E_gel / h_gel) * b * w * w * w / 12.0;
  if (model != "half-space") throw std::invalid_argument("skin.ridge_rocking = '" + model + "': unknown model");
  const double e_star = E_gel / (1.0 - kGelPoisson * kGelPoisson);
  return std::numbers::pi * e_star * b * w * w / 16.0;
}

}  // namespace tactip
