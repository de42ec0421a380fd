#include "models/membrane_elements.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

#include <Eigen/Dense>

namespace tactip {

namespace {

using Vec2 = std::array<double, 2>;

// A pin's place in the arc-length layout, (y, z) in the sensor's plane.
Vec2 Planar(const PinGeometry& pin, double radius_m) {
  const double rho = pin.polar_rad * radius_m;
  return {rho * std::cos(pin.azimuth_rad), rho * std::sin(pin.azimuth_rad)};
}

// The sheet's plane-stress stiffness (N/m) in the polar frame (r, theta, r-theta shear),
// from its compliance: radially softer by the corrugation, hoop and shear by the developed length.
Eigen::Matrix3d PolarStiffness(double membrane_N_m, const Corrugation& c) {
  const double nu = kRubberPoisson;
  Eigen::Matrix3d S;
  S << c.radial_factor, -nu, 0.0, -nu, 1.0 / c.length_ratio, 0.0, 0.0, 0.0, 2.0 * (1.0 + nu) * c.length_ratio;
  return (S / membrane_N_m).inverse();
}

// The same in the y-z frame, the radial direction at angle phi from +y.
Eigen::Matrix3d Rotated(const Eigen::Matrix3d& polar, double phi) {
  const double c = std::cos(phi), s = std::sin(phi);
  Eigen::Matrix3d T;  // polar strain = T * (e_yy, e_zz, g_yz)
  T << c * c, s * s, c * s, s * s, c * c, -c * s, -2.0 * c * s, 2.0 * c * s, c * c - s * s;
  return T.transpose() * polar * T;
}

// A linear triangle's 6x6 stiffness over (y0, z0, y1, z1, y2, z2).
Eigen::Matrix<double, 6, 6> TriangleStiffness(const std::array<Vec2, 3>& p, const Eigen::Matrix3d& polar) {
  const double area2 = (p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[2][0] - p[0][0]) * (p[1][1] - p[0][1]);
  Eigen::Matrix<double, 3, 6> B = Eigen::Matrix<double, 3, 6>::Zero();
  for (int a = 0; a < 3; ++a) {
    const Vec2& q = p[(a + 1) % 3];
    const Vec2& r = p[(a + 2) % 3];
    const double by = q[1] - r[1], bz = r[0] - q[0];  // d N_a / dy, d N_a / dz times area2
    B(0, 2 * a) = by;
    B(1, 2 * a + 1) = bz;
    B(2, 2 * a) = bz;
    B(2, 2 * a + 1) = by;
  }
  B /= area2;
  const double cy = (p[0][0] + p[1][0] + p[2][0]) / 3.0, cz = (p[0][1] + p[1][1] + p[2][1]) / 3.0;
  return 0.5 * std::abs(area2) * B.transpose() * Rotated(polar, std::atan2(cz, cy)) * B;
}

// The pins of each ring, by azimuth (PinLattice::Build's order).
std::vector<std::vector<int>> Rings(const PinLattice& lattice) {
  std::vector<std::vector<int>> rings;
  for (const auto& pin : lattice.pins) {
    if (rings.empty() || pin.ring != lattice.pins[rings.back().front()].ring) rings.emplace_back();
    rings.back().push_back(pin.index);
  }
  return rings;
}

// The band between two rings, walked by azimuth from both rings' first pins: each step
// takes the ring whose next pin comes first.
void StitchBand(const PinLattice& lattice, const std::vector<int>& inner, const std::vector<int>& outer,
                std::vector<std::array<int, 3>>& out) {
  const size_t ni = inner.size(), no = outer.size();
  auto next_az = [&](const std::vector<int>& ring, size_t i) {
    const size_t n = ring.size();
    return i + 1 < n ? lattice.pins[ring[i + 1]].azimuth_rad
                     : lattice.pins[ring[0]].azimuth_rad + 2.0 * std::numbers::pi;
  };
  if (ni == 1) {  // the centre pin: a fan
    for (size_t j = 0; j < no; ++j) out.push_back({inner[0], outer[j], outer[(j + 1) % no]});
    return;
  }
  size_t i = 0, j = 0;
  while (i < ni || j < no) {
    const bool take_outer = j < no && (i >= ni || next_az(outer, j) <= next_az(inner, i) + 1e-12);
    if (take_outer) {
      out.push_back({inner[i % ni], outer[j], outer[(j + 1) % no]});
      ++j;
    } else {
      out.push_back({inner[i], inner[(i + 1) % ni], outer[j % no]});
      ++i;
    }
  }
}
}  // namespace

std::vector<std::array<int, 3>> RingTriangles(const PinLattice& lattice) {
  const std::vector<std::vector<int>> rings = Rings(lattice);
  std::vector<std::array<int, 3>> triangles;
  for (size_t k = 1; k < rings.size(); ++k) StitchBand(lattice, rings[k - 1], rings[k], triangles);
  return triangles;
}

std::vector<WeightedTriangle> SymmetricRingTriangles(const PinLattice& lattice) {
  // The mirror pin: the same ring, azimuth -az (ring k's pin j to pin (n - j) mod n).
  std::vector<int> mirror(lattice.size());
  for (const std::vector<int>& ring : Rings(lattice)) {
    const size_t n = ring.size();
    for (size_t j = 0; j < n; ++j) mirror[ring[j]] = ring[(n - j) % n];
  }
  auto sorted = [](std::array<int, 3> t) {
    std::sort(t.begin(), t.end());
    return t;
  };
  const std::vector<std::array<int, 3>> triangles = RingTriangles(lattice);
  std::set<std::array<int, 3>> own, mirrored;
  for (const auto& t : triangles) {
    own.insert(sorted(t));
    mirrored.insert(sorted({mirror[t[0]], mirror[t[1]], mirror[t[2]]}));
  }
  std::vector<WeightedTriangle> out;
  for (const auto& t : own) out.push_back({t, mirrored.count(t) ? 1.0 : 0.5});
  for (const auto& t : mirrored) {
    if (!own.count(t)) out.push_back({t, 0.5});
  }
  return out;
}

std::vector<MembraneMode> OrthotropicMembraneModes(const SkinMechanics& mech, const PinLattice& lattice) {
  const double radius_m = mech.dome_radius_m;
  const double scale = mech.k_link_N_m > 0.0 ? mech.k_couple_N_m / mech.k_link_N_m : 1.0;
  const Eigen::Matrix3d polar = scale * PolarStiffness(mech.membrane_N_m, mech.corrugation);
  std::vector<MembraneMode> modes;
  for (const auto& [tri, weight] : SymmetricRingTriangles(lattice)) {
    const std::array<Vec2, 3> p = {Planar(lattice.pins[tri[0]], radius_m), Planar(lattice.pins[tri[1]], radius_m),
                                   Planar(lattice.pins[tri[2]], radius_m)};
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> eig(weight * TriangleStiffness(p, polar));
    const double largest = eig.eigenvalues().maxCoeff();
    for (int m = 0; m < 6; ++m) {
      if (eig.eigenvalues()(m) <= 1e-9 * largest) continue;  // the three rigid motions
      MembraneMode mode{tri, {}, eig.eigenvalues()(m)};
      for (int c = 0; c < 6; ++c) mode.coef[c] = eig.eigenvectors()(c, m);
      modes.push_back(mode);
    }
  }
  return modes;
}

}  // namespace tactip
