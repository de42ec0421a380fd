// The orthotropic membrane (skin.membrane_links = orthotropic): the ring lattice's triangles,
// the corrugation's factors, and the triangles' stiffness modes against the plane-stress sheet.

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include "models/membrane_elements.h"
#include "models/preset_skin.h"
#include "models/skin.h"
#include "sim/sim_config.h"

namespace tactip {
namespace {

// The preset on the orthotropic membrane.
SkinConfig Preset(const std::string& name) {
  SkinConfig s = PresetSkin(name);
  s.membrane_links = "orthotropic";
  ValidateConfig(s);
  return s;
}

// (y, z) of a pin in the arc-length layout the membrane is built on.
Eigen::Vector2d Planar(const PinGeometry& pin, double radius_m) {
  const double rho = pin.polar_rad * radius_m;
  return {rho * std::cos(pin.azimuth_rad), rho * std::sin(pin.azimuth_rad)};
}

// The modes' stiffness assembled over every pin's (y, z).
Eigen::MatrixXd Assembled(const std::vector<MembraneMode>& modes, size_t n_pins) {
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(2 * n_pins, 2 * n_pins);
  for (const auto& mode : modes) {
    Eigen::VectorXd a = Eigen::VectorXd::Zero(2 * n_pins);
    for (int c = 0; c < 6; ++c) a(2 * mode.pins[c / 2] + c % 2) = mode.coef[c];
    K += mode.k_N_m * a * a.transpose();
  }
  return K;
}

// The plane-stress sheet's polar stiffness (N/m) from its compliance, as docs/fingerprint-skins.md
// ('Orthotropic membrane') gives it.
Eigen::Matrix3d SheetStiffness(double membrane_N_m, const Corrugation& c) {
  const double nu = 0.5;
  Eigen::Matrix3d S;
  S << c.radial_factor, -nu, 0.0, -nu, 1.0 / c.length_ratio, 0.0, 0.0, 0.0, 2.0 * (1.0 + nu) * c.length_ratio;
  return (S / membrane_N_m).inverse();
}

TEST(RingTrianglesTest, TileThePatternsPolygonWithEveryPinInATriangle) {
  for (const char* name : {"fingerprint-v1", "fingerprint-v2"}) {
    const SkinConfig skin = Preset(name);
    const PinLattice lattice = PinLattice::Build(skin);
    const auto triangles = RingTriangles(lattice);
    const double R = skin.radius_mm * 1e-3;
    double area = 0.0;
    std::set<int> covered;
    for (const auto& t : triangles) {
      const Eigen::Vector2d a = Planar(lattice.pins[t[0]], R), b = Planar(lattice.pins[t[1]], R),
                            c = Planar(lattice.pins[t[2]], R);
      const Eigen::Vector2d u = b - a, v = c - a;
      const double twice = u.x() * v.y() - u.y() * v.x();
      EXPECT_GT(std::abs(twice), 0.0) << name << ": a degenerate triangle";
      area += 0.5 * std::abs(twice);
      covered.insert(t.begin(), t.end());
    }
    // The outermost ring's polygon: n pins on radius K s.
    const int K = lattice.pins.back().ring;
    const int n = skin.pins_per_ring * K;
    const double r = K * skin.ridge_spacing_mm * 1e-3;
    EXPECT_NEAR(area, 0.5 * n * r * r * std::sin(2.0 * std::numbers::pi / n), 1e-9 * area) << name;
    EXPECT_EQ(covered.size(), lattice.size()) << name;
    // Each band between rings k-1 and k: one triangle per pin of either ring.
    EXPECT_EQ(triangles.size(), static_cast<size_t>(skin.pins_per_ring * K * K)) << name;
  }
}

// The stitch and its mirror image: together they still tile the polygon once (weights 1 and
// 1/2), and the set maps onto itself under the mirror (azimuth -> -azimuth).
TEST(RingTrianglesTest, SymmetricTrianglesTileOnceAndAreTheirOwnMirrorImage) {
  const SkinConfig skin = Preset("fingerprint-v2");
  const PinLattice lattice = PinLattice::Build(skin);
  const double R = skin.radius_mm * 1e-3;
  std::map<std::array<int, 3>, double> weight;
  double area = 0.0;
  for (const auto& [t, w] : SymmetricRingTriangles(lattice)) {
    const Eigen::Vector2d a = Planar(lattice.pins[t[0]], R), u = Planar(lattice.pins[t[1]], R) - a,
                          v = Planar(lattice.pins[t[2]], R) - a;
    area += w * 0.5 * std::abs(u.x() * v.y() - u.y() * v.x());
    weight[t] = w;
  }
  const int n = skin.pins_per_ring * 6;
  const double r = 6 * skin.ridge_spacing_mm * 1e-3;
  EXPECT_NEAR(area, 0.5 * n * r * r * std::sin(2.0 * std::numbers::pi / n), 1e-9 * area);
  auto mirror = [&](int pin) {
    const PinGeometry& p = lattice.pins[pin];
    for (const auto& q : lattice.pins) {
      if (q.ring == p.ring && std::abs(std::remainder(q.azimuth_rad + p.azimuth_rad, 2.0 * std::numbers::pi)) < 1e-9) {
        return q.index;
      }
    }
    return -1;
  };
  int halves = 0;
  for (const auto& [t, w] : weight) {
    std::array<int, 3> m = {mirror(t[0]), mirror(t[1]), mirror(t[2])};
    std::sort(m.begin(), m.end());
    ASSERT_TRUE(weight.count(m)) << t[0] << " " << t[1] << " " << t[2];
    EXPECT_EQ(weight.at(m), w);
    halves += w < 1.0 ? 1 : 0;
  }
  EXPECT_GT(halves, 0) << "the stitch alone is not mirror-symmetric";
}

TEST(CorrugationTest, FactorsFollowTheRidgesWavesAndLength) {
  const Corrugation v2 = Corrugation::Of(Preset("fingerprint-v2"));
  // 1 mm waves on a 1 mm skin: 1 + 6 (1 - 1/4) (1/1)^2.
  EXPECT_NEAR(v2.radial_factor, 5.5, 1e-12);
  // The developed length of a sine of amplitude a over period s: (2/pi) sqrt(1 + k^2) E(m),
  // k = 2 pi a / s, m = k^2 / (1 + k^2) (complete elliptic integral of the second kind).
  const double k = 2.0 * std::numbers::pi * 1.0 / 3.0;
  const double modulus = std::sqrt(k * k / (1.0 + k * k));
  EXPECT_NEAR(v2.length_ratio, 2.0 / std::numbers::pi * std::sqrt(1.0 + k * k) * std::comp_ellint_2(modulus), 1e-9);
  const Corrugation v1 = Corrugation::Of(Preset("fingerprint-v1"));
  EXPECT_NEAR(v1.radial_factor, 1.0 + 6.0 * 0.75 * 4.0, 1e-12) << "1 mm (half of 2 mm) on a 0.5 mm skin";
  EXPECT_NEAR(v1.length_ratio, 2.0, 1e-12) << "square ridges 2 mm high every 4 mm: up, across, down";
  const Corrugation flat = Corrugation::Of(SkinConfig{});
  EXPECT_EQ(flat.radial_factor, 1.0);
  EXPECT_EQ(flat.length_ratio, 1.0);
}

struct V2Membrane {
  SkinConfig skin = Preset("fingerprint-v2");
  PinLattice lattice = PinLattice::Build(skin);
  SkinMechanics mech = SkinMechanics::From(skin, lattice);
  double scale = mech.k_couple_N_m / mech.k_link_N_m;
  // Displacements of a linear field u(p) = G p over the lattice.
  Eigen::VectorXd Field(const Eigen::Matrix2d& G) const {
    Eigen::VectorXd u(2 * lattice.size());
    for (const auto& pin : lattice.pins) u.segment<2>(2 * pin.index) = G * Planar(pin, mech.dome_radius_m);
    return u;
  }
  double PolygonArea() const {
    const int n = static_cast<int>(lattice.size()) - 1 - 3 * 5 * 6;  // the outer ring's pins
    const double r = 6 * skin.ridge_spacing_mm * 1e-3;
    return 0.5 * n * r * r * std::sin(2.0 * std::numbers::pi / n);
  }
};

TEST(OrthotropicMembraneTest, RigidMotionsCarryNoForceAndEachTriangleHasThreeModes) {
  const V2Membrane v2;
  const auto modes = OrthotropicMembraneModes(v2.mech, v2.lattice);
  EXPECT_EQ(modes.size(), 3 * SymmetricRingTriangles(v2.lattice).size());
  const Eigen::MatrixXd K = Assembled(modes, v2.lattice.size());
  Eigen::Matrix2d translate_y, rotate;
  translate_y.setZero();
  rotate << 0.0, -1.0, 1.0, 0.0;
  Eigen::VectorXd shift = Eigen::VectorXd::Zero(2 * v2.lattice.size());
  for (size_t i = 0; i < v2.lattice.size(); ++i) shift(2 * i) = 1e-3;
  const double scale = K.cwiseAbs().maxCoeff() * 1e-3;
  EXPECT_LT((K * shift).cwiseAbs().maxCoeff(), 1e-9 * scale) << "a translation stretches nothing";
  EXPECT_LT((K * v2.Field(1e-3 * rotate)).cwiseAbs().maxCoeff(), 1e-9 * scale) << "nor a small rotation";
  for (const auto& m : modes) EXPECT_GT(m.k_N_m, 0.0);
}

// A uniform expansion strains every triangle alike in any frame (e_rr = e_tt = e, no shear), so
// the lattice's energy is the sheet's: (1/2) e^2 (D_rr + 2 D_rt + D_tt) times the area.
TEST(OrthotropicMembraneTest, UniformExpansionStoresTheCorrugatedSheetsEnergy) {
  const V2Membrane v2;
  const Eigen::MatrixXd K = Assembled(OrthotropicMembraneModes(v2.mech, v2.lattice), v2.lattice.size());
  const double e = 1e-3;
  const Eigen::VectorXd u = v2.Field(e * Eigen::Matrix2d::Identity());
  const Eigen::Matrix3d D = v2.scale * SheetStiffness(v2.mech.membrane_N_m, v2.mech.corrugation);
  const double sheet = 0.5 * e * e * (D(0, 0) + 2.0 * D(0, 1) + D(1, 1)) * v2.PolygonArea();
  EXPECT_NEAR(0.5 * u.dot(K * u), sheet, 1e-9 * sheet);
}

// The flat sheet (no corrugation) is isotropic: a uniform uniaxial strain leaves every
// interior pin without force (the linear triangle's patch test) and stores E t e^2 / (2 (1 -
// nu^2)) per area.
TEST(OrthotropicMembraneTest, FlatSheetPassesThePatchTestAndStoresThePlaneStressEnergy) {
  V2Membrane v2;
  v2.mech.corrugation = Corrugation{};
  const size_t n = v2.lattice.size();
  const Eigen::MatrixXd K = Assembled(OrthotropicMembraneModes(v2.mech, v2.lattice), n);
  Eigen::Matrix2d G;
  G << 1e-3, 0.0, 0.0, 0.0;
  const Eigen::VectorXd u = v2.Field(G), f = K * u;
  const int outer = v2.lattice.pins.back().ring;
  double interior = 0.0, edge = 0.0;
  for (const auto& pin : v2.lattice.pins) {
    const double force = f.segment<2>(2 * pin.index).norm();
    (pin.ring < outer ? interior : edge) = std::max(pin.ring < outer ? interior : edge, force);
  }
  EXPECT_LT(interior, 1e-9 * edge);
  const double flat = 0.5 * u.dot(K * u);
  const double E_t = v2.scale * v2.mech.membrane_N_m;
  EXPECT_NEAR(flat, 0.5 * E_t / (1.0 - 0.25) * 1e-6 * v2.PolygonArea(), 1e-9 * flat);
}

// Stretched along y the corrugated sheet's stiffness depends on where a triangle sits: D_yy =
// c^4 D_rr + 2 c^2 s^2 (D_rt + 2 D_ss) + s^4 D_tt with c, s the cosine and sine of its radial
// direction, so the lattice stores the sum over its triangles of (1/2) e^2 D_yy times the area —
// radially softer where the stretch runs across the ridges (on the y axis), hoop-stiff across it.
TEST(OrthotropicMembraneTest, StretchAcrossTheRidgesIsSoftAndAlongThemStiff) {
  const V2Membrane v2;
  const Eigen::MatrixXd K = Assembled(OrthotropicMembraneModes(v2.mech, v2.lattice), v2.lattice.size());
  const double e = 1e-3;
  Eigen::Matrix2d G;
  G << e, 0.0, 0.0, 0.0;
  const Eigen::VectorXd u = v2.Field(G);
  const Eigen::Matrix3d D = v2.scale * SheetStiffness(v2.mech.membrane_N_m, v2.mech.corrugation);
  double expected = 0.0, across = 0.0, along = 0.0;
  for (const auto& t : RingTriangles(v2.lattice)) {
    Eigen::Vector2d p[3];
    for (int k = 0; k < 3; ++k) p[k] = Planar(v2.lattice.pins[t[k]], v2.mech.dome_radius_m);
    const Eigen::Vector2d u1 = p[1] - p[0], u2 = p[2] - p[0], centroid = (p[0] + p[1] + p[2]) / 3.0;
    const double area = 0.5 * std::abs(u1.x() * u2.y() - u1.y() * u2.x());
    const double c = centroid.x() / centroid.norm(), s = centroid.y() / centroid.norm();
    const double D_yy = c * c * c * c * D(0, 0) + 2.0 * c * c * s * s * (D(0, 1) + 2.0 * D(2, 2)) + s * s * s * s * D(1, 1);
    expected += 0.5 * e * e * D_yy * area;
    if (std::abs(c) > 0.99) across = D_yy;
    if (std::abs(s) > 0.99) along = D_yy;
  }
  EXPECT_NEAR(0.5 * u.dot(K * u), expected, 1e-9 * expected);
  EXPECT_LT(across, 0.25 * along) << "across the ridges the waves bend; along them the rubber stretches";
}

}  // namespace
}  // namespace tactip
