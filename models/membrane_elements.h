#pragma once
// The orthotropic membrane of a fingerprint skin (skin.membrane_links = orthotropic): the
// skin between the pins as linear triangles of a corrugated sheet, each triangle's in-plane
// stiffness over its three pins' shear DOFs split into its three stiffness modes (one fixed
// tendon each in the MJCF, one rank-1 term each in the exact quasi-static solution).

#include <array>
#include <vector>

#include "models/pin_lattice.h"
#include "models/skin_mechanics.h"

namespace tactip {

/// One stiffness mode of a membrane triangle: the spring k (a^T u)^2 / 2 over its pins'
/// shear DOFs, a = (y0, z0, y1, z1, y2, z2) a unit vector.
struct MembraneMode {
  std::array<int, 3> pins{};
  std::array<double, 6> coef{};
  double k_N_m = 0.0;
};

/// Triangles of a ring lattice (PinLattice::Build on a fingerprint pattern): each band between
/// two consecutive rings stitched by azimuth, so the triangles tile the pattern's polygon.
std::vector<std::array<int, 3>> RingTriangles(const PinLattice& lattice);

/// RingTriangles with its mirror image (every pin to its mirror across the azimuth-0 axis): the
/// stitch picks one diagonal where two rings' pins line up, its mirror the other, so each
/// triangle the two share weighs 1 and each of the others 1/2, and the membrane keeps the
/// lattice's mirror symmetry (the sides and the poles of a shear load alike).
struct WeightedTriangle {
  std::array<int, 3> pins{};
  double weight = 1.0;
};
std::vector<WeightedTriangle> SymmetricRingTriangles(const PinLattice& lattice);

/// The membrane's modes on this lattice (SymmetricRingTriangles): plane-stress triangles of the corrugated sheet
/// (E t radially soft by the corrugation, hoop stiff, shear along the developed path), in the
/// polar frame at each triangle's centroid (mech.corrugation), scaled by k_couple / k_link (the ridges' rocking in
/// series, as for the isotropic links). Positions: the pins' arc-length layout in the sensor's
/// y-z plane.
std::vector<MembraneMode> OrthotropicMembraneModes(const SkinMechanics& mech, const PinLattice& lattice);

}  // namespace tactip
