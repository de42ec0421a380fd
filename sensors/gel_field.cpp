#include "sensors/gel_field.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tactip {

namespace {

// A pin's position in the skin's flattened (azimuthal-equidistant) plane: arc length from
// the apex as the radius, the azimuth as the angle.
std::array<double, 2> Planar(const PinGeometry& pin, double radius_m) {
  const double rho = pin.polar_rad * radius_m;
  return {rho * std::cos(pin.azimuth_rad), rho * std::sin(pin.azimuth_rad)};
}

// A planar vector at `pin` as a vector along the dome's surface, in the sensor frame:
// its radial part along the meridian (away from the apex), its azimuthal part along the
// parallel.
std::array<double, 3> OnDome(const PinGeometry& pin, const std::array<double, 2>& v) {
  const double ct = std::cos(pin.polar_rad), st = std::sin(pin.polar_rad);
  const double cp = std::cos(pin.azimuth_rad), sp = std::sin(pin.azimuth_rad);
  const double radial = v[0] * cp + v[1] * sp, azimuthal = -v[0] * sp + v[1] * cp;
  return {-st * radial, ct * cp * radial - sp * azimuthal, ct * sp * radial + cp * azimuthal};
}

}  // namespace

GelField GelField::Build(const SkinConfig& skin, const PinLattice& lattice) {
  GelField field;
  if (skin.marker_model != "gel") return field;
  const int n = static_cast<int>(lattice.size());
  const SkinMechanics mech = SkinMechanics::From(skin, lattice);
  const double radius_m = skin.radius_mm * 1e-3;
  const double flow_depth_m = skin.gel_flow_depth_mm * 1e-3;
  // Each pin's source spreads over its cell: half the lattice step.
  const double spread_m = 0.5e-3 * (skin.Fingerprint() ? skin.ridge_spacing_mm : skin.pitch_mm);
  // The gel is bonded to the rigid core: the flow dies out over the gel's depth.
  const double screening_m = skin.gel_depth_mm * 1e-3;
  field.n_ = n;
  field.squeeze_m_ = skin.gel_squeeze_mm * 1e-3;
  field.influence_.assign(static_cast<size_t>(n) * n * 3, 0.0);
  // Volume q A squeezed out at pin j flows radially through a layer of depth h: at distance
  // s the layer moves by q A / (2 pi h s) exp(-s / gel depth), regularised over the
  // source's cell.
  const double gain = mech.cell_area_m2 / (2.0 * std::numbers::pi * flow_depth_m);
  for (int i = 0; i < n; ++i) {
    const auto pi = Planar(lattice.pins[i], radius_m);
    for (int j = 0; j < n; ++j) {
      if (i == j) continue;
      const auto pj = Planar(lattice.pins[j], radius_m);
      const std::array<double, 2> d{pi[0] - pj[0], pi[1] - pj[1]};
      const double s2 = d[0] * d[0] + d[1] * d[1];
      const double k = gain * std::exp(-std::sqrt(s2) / screening_m) / (s2 + spread_m * spread_m);
      const auto v = OnDome(lattice.pins[i], {k * d[0], k * d[1]});
      std::copy(v.begin(), v.end(), field.influence_.begin() + (static_cast<size_t>(j) * n + i) * 3);
    }
  }
  return field;
}

double GelField::Squeeze(double indentation_m) const {
  return indentation_m > 0.0 ? squeeze_m_ * std::tanh(indentation_m / squeeze_m_) : 0.0;
}

void GelField::Shifts(const std::vector<double>& indentation_m, std::vector<std::array<double, 3>>& shift) const {
  shift.assign(static_cast<size_t>(n_), {0.0, 0.0, 0.0});
  // Superpose every squeezing pin's flow on every marker (for each marker the sources are
  // added in pin order).
  for (int j = 0; j < n_; ++j) {
    const double q = Squeeze(indentation_m[j]);
    if (q == 0.0) continue;
    const double* k = influence_.data() + static_cast<size_t>(j) * n_ * 3;
    for (int i = 0; i < n_; ++i) {
      for (int c = 0; c < 3; ++c) shift[i][c] += k[3 * i + c] * q;
    }
  }
}

}  // namespace tactip
