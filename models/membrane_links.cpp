#include "models/membrane_links.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "models/membrane_elements.h"

namespace tactip {

double SkinMechanics::CentralLinkStiffness(double radial_share) const {
  // No ridges: the membrane spring alone; else in series with both ridges' rocking at the share.
  if (!(k_rock_N_m > 0.0)) return k_link_N_m;
  return 1.0 / (1.0 / k_link_N_m + 2.0 * radial_share * radial_share / k_rock_N_m);
}

SkinMechanics::CentralLink SkinMechanics::CentralLinkBetween(const PinGeometry& a, const PinGeometry& b) const {
  // Pins sit on the dome along their normals, so the normals' difference is the link's
  // direction and their sum the radial direction at its midpoint (a link through the apex
  // is radial).
  const double ey = b.normal[1] - a.normal[1], ez = b.normal[2] - a.normal[2];
  const double length = std::hypot(ey, ez);
  const double ry = a.normal[1] + b.normal[1], rz = a.normal[2] + b.normal[2];
  const double r = std::hypot(ry, rz);
  const double radial_share = r < 1e-9 * length ? 1.0 : std::abs(ey * ry + ez * rz) / (length * r);
  return {ey / length, ez / length, CentralLinkStiffness(radial_share)};
}

namespace {
// The widest row of a lattice's shear stiffness: each pin's own spring plus the larger of its
// two axes' coupling rows (`row`, entries added by magnitude).
double WidestShearRow(const SkinMechanics& m, const PinLattice& lattice, const std::vector<std::array<double, 2>>& row) {
  double widest = 0.0;
  for (const auto& pin : lattice.pins) {
    widest = std::max(widest, m.TipStiffness(pin.ring) + std::max(row[pin.index][0], row[pin.index][1]));
  }
  return widest;
}
}  // namespace

double CentralRowMax(const SkinMechanics& m, const PinLattice& lattice) {
  // Each link's entries, by magnitude, on the rows of both its pins' axes.
  std::vector<std::array<double, 2>> row(lattice.size(), {0.0, 0.0});
  for (const auto& e : lattice.neighbours) {
    const SkinMechanics::CentralLink l = m.CentralLinkBetween(lattice.pins[e[0]], lattice.pins[e[1]]);
    const double both = 2.0 * (std::abs(l.ey) + std::abs(l.ez));
    for (int pin : e) {
      row[pin][0] += l.k_N_m * std::abs(l.ey) * both;
      row[pin][1] += l.k_N_m * std::abs(l.ez) * both;
    }
  }
  return WidestShearRow(m, lattice, row);
}

double OrthotropicRowMax(const SkinMechanics& m, const PinLattice& lattice) {
  // Each mode's entries, by magnitude, on the rows of its three pins' axes.
  std::vector<std::array<double, 2>> row(lattice.size(), {0.0, 0.0});
  for (const MembraneMode& mode : OrthotropicMembraneModes(m, lattice)) {
    double sum = 0.0;
    for (double c : mode.coef) sum += std::abs(c);
    for (int c = 0; c < 6; ++c) row[mode.pins[c / 2]][c % 2] += mode.k_N_m * std::abs(mode.coef[c]) * sum;
  }
  return WidestShearRow(m, lattice, row);
}

}  // namespace tactip
