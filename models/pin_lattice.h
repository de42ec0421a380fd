#pragma once
// The pin lattice on the dome: the smooth skin's hexagonal lattice and the fingerprint skins'
// concentric rings, each wrapped onto the hemisphere, with the neighbour pairs the skin couples.

#include <array>
#include <cstddef>
#include <vector>

#include "models/skin_config.h"

namespace tactip {

/// One pin of the lattice in the sensor frame (x = dome axis, outwards; z = up).
struct PinGeometry {
  int index = 0;                        ///< 0 = centre pin
  int ring = 0;                         ///< hexagonal ring (0 = centre)
  double polar_rad = 0.0;               ///< angle from the dome axis
  double azimuth_rad = 0.0;             ///< angle around the axis, from +y towards +z
  std::array<double, 3> normal{};       ///< outward unit normal of the dome at the pin
};

/// Pin positions and neighbour pairs of a hexagonal lattice wrapped on the dome
/// (azimuthal-equidistant: arc length from the apex = planar distance).
struct PinLattice {
  std::vector<PinGeometry> pins;                ///< ordered by ring, then azimuth
  std::vector<std::array<int, 2>> neighbours;   ///< lattice edges (i < j)

  /// Builds the lattice; throws InputError if it does not fit on the hemisphere.
  static PinLattice Build(const SkinConfig& skin);
  /// Number of pins.
  size_t size() const { return pins.size(); }
};

}  // namespace tactip
